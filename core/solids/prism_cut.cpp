#include "core/solids/prism_cut.h"

#include "core/base/enum_names.h"
#include "core/base/errors.h"
#include "core/field/csg_combine.h"
#include "core/primitives/sdf_rasterizer.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

constexpr EnumNames<PrismMode, 2> kModes{{{PrismMode::Cut, "cut"}, {PrismMode::Fill, "fill"}}};

/// Signed distance from q to the closed polygon (negative inside, by the even-odd rule).
double polygonDistance(const std::vector<openvdb::Vec2d>& polygon, const openvdb::Vec2d& q)
{
    double nearest = std::numeric_limits<double>::infinity();
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const openvdb::Vec2d a = polygon[j], b = polygon[i], ab = b - a;
        const double t = std::clamp((q - a).dot(ab) / std::max(ab.lengthSqr(), 1e-300), 0.0, 1.0);
        nearest = std::min(nearest, (q - (a + ab * t)).length());
        if ((a.y() > q.y()) != (b.y() > q.y()) && q.x() < a.x() + (q.y() - a.y()) / (b.y() - a.y()) * ab.x())
            inside = !inside;
    }
    return inside ? -nearest : nearest;
}

/// The distance to the box `bounds` (negative inside).
double boxDistance(const openvdb::BBoxd& bounds, const openvdb::Vec3d& p)
{
    const openvdb::Vec3d centre = bounds.getCenter(), half = bounds.extents() * 0.5;
    const openvdb::Vec3d q(std::abs(p.x() - centre.x()) - half.x(), std::abs(p.y() - centre.y()) - half.y(),
                           std::abs(p.z() - centre.z()) - half.z());
    const openvdb::Vec3d outside(std::max(q.x(), 0.0), std::max(q.y(), 0.0), std::max(q.z(), 0.0));
    return outside.length() + std::min(std::max({q.x(), q.y(), q.z()}), 0.0);
}

}  // namespace

PrismMode prismModeFromName(const std::string& name) { return enumFromName(kModes, name, "cut mode"); }

const char* prismModeName(PrismMode mode) { return enumName(kModes, mode); }

void validatePrism(const ViewPrism& prism)
{
    if (prism.polygon.size() < 3) throw InputError("a gesture's polygon needs three points at least");
    for (const openvdb::Vec2d& p : prism.polygon)
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
            throw InputError("a gesture's polygon has a point not finite");
    if (!(prism.nearDepth < prism.farDepth))
        throw InputError("a gesture's depth slab is empty (near is not before far)");
}

double ViewPrism::distance(const openvdb::Vec3d& world) const
{
    double best = std::numeric_limits<double>::infinity();
    for (int m = 0; m < 8; ++m) {
        if (((m & 1) && !mirror[0]) || ((m & 2) && !mirror[1]) || ((m & 4) && !mirror[2])) continue;
        const openvdb::Vec3d p(m & 1 ? -world.x() : world.x(), m & 2 ? -world.y() : world.y(),
                               m & 4 ? -world.z() : world.z());
        const openvdb::Vec3d v = viewFromWorld.transform(p);
        const double depth = -v.z();
        const double slab = std::max(nearDepth - depth, depth - farDepth);
        double across;
        if (!perspective) {
            across = polygonDistance(polygon, {v.x(), v.y()});
        } else if (depth > 1e-9) {
            across = polygonDistance(polygon, {v.x() / depth, v.y() / depth}) * depth;
        } else {
            across = -depth + 1e-9;  // behind the eye: outside, by about the distance to its plane
        }
        best = std::min(best, std::max(across, slab));
    }
    return best;
}

std::vector<openvdb::Vec2d> halfPlanePolygon(const openvdb::Vec2d& a, const openvdb::Vec2d& b, double reach)
{
    const openvdb::Vec2d along = (b - a).length() > 0.0 ? (b - a).unitSafe() : openvdb::Vec2d(1.0, 0.0);
    const openvdb::Vec2d right(along.y(), -along.x());
    const openvdb::Vec2d from = a - along * reach, to = b + along * reach;
    return {from, to, to + right * reach, from + right * reach};
}

FieldImage applyPrism(const FieldImage& field, const ViewPrism& prism, PrismMode mode)
{
    validatePrism(prism);
    if (mode == PrismMode::Fill && !std::isfinite(prism.farDepth))
        throw InputError("a fill needs a depth (how far along the view it reaches)");
    openvdb::CoordBBox leaves;
    field.grid().tree().evalLeafBoundingBox(leaves);
    openvdb::BBoxd reach = field.grid().transform().indexToWorld(leaves);
    // A fill may reach beyond the model: its own box is bounded by the slab, unknown here, so the
    // model's box grows by the slab's far depth at most.
    const double grow = 2.0 * field.grid().background() +
                        (mode == PrismMode::Fill ? std::min(prism.farDepth, reach.extents().length()) : 0.0);
    reach.expand(grow);
    AnalyticSdf sdf;
    sdf.distance = [&](const openvdb::Vec3d& p) { return std::max(prism.distance(p), boxDistance(reach, p)); };
    sdf.bounds = reach;
    const openvdb::Vec3d e = reach.extents();
    sdf.surfaceArea = 2.0 * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
    sdf.description = "cut";
    FieldImage tool = rasterizeSdf(sdf, field.voxelSize(), field.halfWidthVoxels());
    openvdb::FloatGrid::Ptr result = field.grid().deepCopy();
    openvdb::FloatGrid::Ptr shape = tool.mutableGridPtr();
    shape->setTransform(result->transform().copy());
    combineWhole(*result, *shape, mode == PrismMode::Cut ? CsgOperation::Difference : CsgOperation::Union);
    FieldImage out(result, field.units());
    out.setMask(field.maskPtr());
    return out;
}

}  // namespace sculpt
