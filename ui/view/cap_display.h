// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file cap_display.h
/// @brief The caps of the clip plane's cut: each visible piece's section by the plane
///        (crossSection, from its field), drawn flat in a darker shade of its colour where the
///        clipped clay would show its inside. A cap is made again only when its piece's field,
///        look or the plane changed.

#include "core/field/field_image.h"
#include "core/field/piece.h"
#include "core/solids/cross_section.h"

#include <vtkSmartPointer.h>

#include <cstdint>
#include <optional>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace sculpt {
class IncrementalMesher;
}

namespace sculpt::ui {

/// A piece as cut by a plane (a cap, a slice's contour): its look, the colour it is drawn in (the sculpted piece's is the clay's), and
/// its field at a version (the mesher's).
struct FieldPiece {
    const PieceLook* look;
    openvdb::Vec3f colour;
    bool sculpted;  ///< the piece being sculpted
    const FieldImage* field;
    const IncrementalMesher* mesher;  ///< its live mesh: what changed since a version
    std::uint64_t version;
};

class CapDisplay {
public:
    explicit CapDisplay(vtkRenderer* renderer);
    ~CapDisplay();

    /// Caps each visible piece's cut by `plane` (world; none: no caps).
    void sync(const std::vector<FieldPiece>& pieces, const std::optional<SectionPlane>& plane,
              std::uint64_t planeRevision);
    /// The caps' area in the world, and their triangles.
    double area() const;
    std::size_t triangleCount() const;
    /// How many times a cap was made (a stroke away from the plane makes none).
    std::size_t remakes() const { return mRemakes; }

private:
    struct Cap;
    void remake(Cap& cap, const FieldPiece& piece, const SectionPlane& plane);

    /// Whether the blocks changed in `piece` since `version` reach the plane (with a margin for
    /// the interpolation of the voxels they hold): only then can its cap change.
    static bool changedNear(const FieldPiece& piece, std::uint64_t version, const SectionPlane& plane);

    vtkRenderer* mRenderer;
    std::vector<Cap> mCaps;
    std::size_t mRemakes = 0;
};

}  // namespace sculpt::ui
