// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file open_preview.h
/// @brief The coarse surface a job making a document (open, import) hands the window before
///        the document is ready.
///
/// The job's thread offers the field once read or converted; if its full mesh would exceed the
/// budget, a preview (previewMesh) is made and left here, and the UI thread takes it at its next
/// frame. A model under the budget opens fast enough to show whole, so it gets none.

#include "core/field/field_image.h"
#include "core/mesh/triangle_mesh.h"

#include <mutex>
#include <optional>

namespace sculpt::ui {

class OpenPreview {
public:
    /// Models whose full mesh is estimated above this many triangles get a preview of about as
    /// many: Mesa draws that in a few tens of milliseconds.
    static constexpr std::size_t kDefaultTriangleBudget = 1'000'000;

    explicit OpenPreview(std::size_t triangleBudget = kDefaultTriangleBudget) : mBudget(triangleBudget) {}

    struct Surface {
        TriangleMesh mesh;                    ///< world coordinates
        openvdb::math::Transform::Ptr xform;  ///< the field's
    };

    /// On the job's thread: makes the preview of `field` if it needs one.
    void offer(const FieldImage& field);
    /// On the UI thread: the preview, once, when it is ready.
    std::optional<Surface> take();

private:
    const std::size_t mBudget;
    std::mutex mMutex;
    std::optional<Surface> mSurface;
};

}  // namespace sculpt::ui
