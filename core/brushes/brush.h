// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file brush.h
/// @brief Sculpting brushes: what one stamp (dab) of a stroke does to the field.
///
/// Every stamp works on a LocalPatch around it: the tool changes the copy's values, the copy is
/// redistanced, and only the voxels inside the tool's region are written back, each leaf saved
/// in the stroke's journal first. The cost follows the brush, never the model.
///
/// Tools (r = radius, s = strength, p = pressure, w = falloff at the voxel's closest surface point):
///   add / carve   union / difference of a ball of radius r s p, swept from the previous stamp
///                 (a capsule: a fast stroke leaves no beads); the falloff sets the fillet where it
///                 meets the surface (constant: a crisp crease ... smooth: a soft blend);
///   inflate / deflate  the surface moves along its normal by 0.1 r s p w per stamp;
///   smooth        mean-curvature flow for beta t = s p h^2, beta weighted by w; with keepVolume
///                 the volume lost under the brush is given back by an inflate of the same falloff;
///   flatten       the surface moves a fraction s p w of its distance to the plane fitted (least
///                 squares) to the surface under the brush;
///   grab          the surface under the brush follows the drag from the previous stamp, by s w of it;
///   pinch         the surface moves towards the stroke line (through the stamp, along the stroke;
///                 along the view direction for a lone stamp) by 0.5 s p w of its distance to it;
///   follow        the surface moves a fraction s p w of its signed distance to a target surface,
///                 read at its closest point: the target term of the level-set motion, only
///                 where the brush goes (a rough import snaps to a clean template under it);
///   primitive     the primitive set, moved to the stamp, combined by its own operation;
///   mask / unmask adds s p w to the mask (FieldImage::mask) / takes it away, within [0, 1]: the
///                 surface does not move.
/// Every tool but the mask's holds the share of its change the mask holds (surface_mask.h).
/// Motions larger than a voxel are split into sub-steps of at most one voxel, each redistanced,
/// so the band stays a distance field. Everything is deterministic, whatever the thread count.

#include "core/field/field_image.h"
#include "core/local/capsule.h"
#include "core/local/falloff.h"
#include "core/primitives/primitive_set.h"

#include <memory>
#include <string>

namespace sculpt {

class LeafJournal;
enum class CsgOperation;

enum class BrushTool { Add, Carve, Inflate, Deflate, Smooth, Flatten, Grab, Pinch, Follow, Primitive, Mask, Unmask };
/// The number of tools: every value below it is a BrushTool (Unmask is the last).
inline constexpr int kBrushToolCount = int(BrushTool::Unmask) + 1;

/// "add", "carve", ... "follow", "primitive", "mask", "unmask". @throws InputError for other names, listing the valid ones.
BrushTool brushToolFromName(const std::string& name);
const char* brushToolName(BrushTool tool);

/// A primitive set to stamp, and how it combines with the sculpt.
struct PrimitiveStamp {
    PrimitiveSet primitives;
    CsgOperation operation;
};

struct BrushSettings {
    BrushTool tool = BrushTool::Add;
    double radiusWorld = 1.0;
    double strength = 0.5;  ///< (0, 1]
    Falloff falloff = Falloff::Smooth;
    bool keepVolume = false;                          ///< smooth only
    std::shared_ptr<const PrimitiveStamp> primitive;  ///< primitive only; positioned at the origin
    std::shared_ptr<const FieldImage> target;         ///< follow only; any voxel size, same world

    /// @throws InputError naming the field: radius not positive and finite, strength not in
    ///         (0, 1], a primitive tool without primitives, a follow tool without a target.
    void validate() const;
};

/// One dab of a stroke.
struct BrushStamp {
    openvdb::Vec3d centreWorld{0.0};
    openvdb::Vec3d previousWorld{0.0};  ///< the stroke's previous stamp; == centre for the first
    double pressure = 1.0;              ///< (0, 1]
    openvdb::Vec3d viewDirection{0.0, 0.0, -1.0};
};

/// Applies one stamp; saves each leaf in `journal` (may be null) before its first change.
/// Marks the changed leaves dirty in `field` and returns them.
DirtyRegion applyStamp(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);

}  // namespace sculpt
