// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file primitive_draft.h
/// @brief The Primitives panel's scene before it is baked: the primitives being placed and
///        tuned, the scene's iso-value and operation, the one selected, and their blended surface
///        previewed on the document's voxels (rebuilt whenever the scene changes).

#include "core/field/field_image.h"
#include "core/primitives/scene_file.h"

#include <optional>
#include <string>
#include <vector>

namespace sculpt::ui {

class PrimitiveDraft {
public:
    /// Previews on `voxels` (the document's lattice).
    explicit PrimitiveDraft(openvdb::math::Transform::ConstPtr voxels);

    std::vector<Primitive> primitives;
    double iso = 0.5;
    CsgOperation operation = CsgOperation::Union;
    int selected = -1;  ///< index into primitives, or -1

    /// A primitive with a `type` skeleton centred at `at`, its kernel reaching `reach`; selected.
    void add(SkeletonType type, const openvdb::Vec3d& at, double reach);
    void removeSelected();
    /// Moves the selected primitive so that its skeleton's centre is at `at`.
    void moveSelectedTo(const openvdb::Vec3d& at);
    /// Replaces the draft by a scene's primitives (a scene file loaded).
    void load(const Scene& scene);

    /// The scene as drawn. @throws InputError naming the primitive at fault.
    Scene scene() const;
    /// Rebuilds the preview if the scene changed since it was made; true if it did. On an error
    /// (a degenerate skeleton, an iso-value no primitive reaches) there is no preview and
    /// problem() says why.
    bool refresh();
    const FieldImage* preview() const { return mPreview ? &*mPreview : nullptr; }
    const std::string& problem() const { return mProblem; }

private:
    openvdb::math::Transform::ConstPtr mVoxels;
    std::optional<FieldImage> mPreview;
    std::string mProblem;
    std::string mPreviewed;  // the scene (as written) the preview or problem is of
    bool mEver = false;      // a preview was attempted
};

/// The centre of a skeleton: its point, segment midpoint, triangle centroid or box centre.
openvdb::Vec3d skeletonCentre(const Skeleton& skeleton);

}  // namespace sculpt::ui
