// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file prism_cut.h
/// @brief Cutting or filling along the view: a polygon drawn on the screen (a box, a lasso, the
///        half-plane beside a line) swept along the view rays into a prism (a pyramid for a
///        perspective view), clipped to a depth slab, and combined with the solid by CSG.
///
/// The prism's signed distance is the polygon's 2D distance in the view plane (scaled by the
/// depth for a perspective view: about world units at that depth) intersected with the slab. It is
/// rasterized as a narrow band only within the model's box grown by two bands (candidate leaves by
/// their centres' distance, sdf_rasterizer.h) and combined with OpenVDB's csgDifference (cut) or
/// csgUnion (fill), which handles the solid's inside tiles without splitting them.

#include "core/field/field_image.h"

#include <openvdb/openvdb.h>

#include <array>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace sculpt {

enum class PrismMode { Cut, Fill };

/// "cut", "fill". @throws InputError for other names.
PrismMode prismModeFromName(const std::string& name);
const char* prismModeName(PrismMode mode);

struct ViewPrism {
    /// View from world: the camera's frame, looking down its -z axis.
    openvdb::Mat4d viewFromWorld = openvdb::Mat4d::identity();
    /// Rays from the eye (the view's origin) through the polygon; else parallel to -z.
    bool perspective = false;
    /// The polygon, closed, in the view plane: (x, y) / depth for a perspective view (the tangents
    /// of the rays' angles), world units for a parallel one. Three vertices at least.
    std::vector<openvdb::Vec2d> polygon;
    /// The slab along the view (depth = -z in view space) the prism spans; a fill needs a finite far.
    double nearDepth = -std::numeric_limits<double>::infinity();
    double farDepth = std::numeric_limits<double>::infinity();
    /// Mirrored across x = 0, y = 0, z = 0 (world) too: the union of the mirrored prisms.
    std::array<bool, 3> mirror{false, false, false};

    /// Signed distance from a world point to the prism (negative inside).
    double distance(const openvdb::Vec3d& world) const;
};

/// @throws InputError for a polygon of fewer than three vertices or not finite, or a slab that is
///         empty.
void validatePrism(const ViewPrism& prism);

class EdgeBins;

/// How far (in voxels) a gesture's polygon may move when a cut or a mask simplifies it
/// (PrismDistance's tolerance): a tenth of a voxel, which the rasterized band cannot show.
inline constexpr double kPolygonToleranceVoxels = 0.1;

/// A prism's distance for many points within a box (every voxel of a cut's band): exact where it
/// is under `capWorld`, beyond that a value of the right sign at least `capWorld` from zero. The
/// polygon's edges are binned in cells a quarter of the cap wide (at the box's farthest depth, for
/// a perspective prism), so a point reads the edges of the few cells nearest it instead of every
/// edge. With `toleranceWorld` > 0 the polygon is first simplified (Douglas-Peucker) by at most
/// that much anywhere in the box: a lasso of 100,000 points drawn finer than a voxel costs about
/// what its shape does. Cheap to copy; read from any thread.
class PrismDistance {
public:
    PrismDistance(const ViewPrism& prism, double capWorld, const openvdb::BBoxd& box, double toleranceWorld = 0.0);
    double operator()(const openvdb::Vec3d& world) const;

private:
    ViewPrism mPrism;
    double mCap;
    std::shared_ptr<const EdgeBins> mBins;
};

/// The half-plane to the right of the line from a to b (view-plane coordinates, as the polygon's),
/// as a polygon reaching `reach` beyond both: a line gesture's prism.
std::vector<openvdb::Vec2d> halfPlanePolygon(const openvdb::Vec2d& a, const openvdb::Vec2d& b, double reach);

/// `field` cut by (or filled with) the prism. Only the prism's band within the model's reach is
/// rasterized. @throws InputError for a polygon of fewer than three vertices or not finite, a slab
/// that is empty, or a fill without a finite far depth.
FieldImage applyPrism(const FieldImage& field, const ViewPrism& prism, PrismMode mode);

}  // namespace sculpt
