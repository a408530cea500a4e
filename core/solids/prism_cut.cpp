// SPDX-License-Identifier: Apache-2.0
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

/// Squared distance from q to the segment from a to b.
double segmentDistance2(const openvdb::Vec2d& a, const openvdb::Vec2d& b, const openvdb::Vec2d& q)
{
    const openvdb::Vec2d ab = b - a, aq = q - a;
    const double t = std::clamp(aq.dot(ab) / std::max(ab.lengthSqr(), 1e-300), 0.0, 1.0);
    return (aq - ab * t).lengthSqr();
}

/// Whether the segment from a to b crosses the ray from q along +x (the even-odd rule's count).
bool crossesRay(const openvdb::Vec2d& a, const openvdb::Vec2d& b, const openvdb::Vec2d& q)
{
    return (a.y() > q.y()) != (b.y() > q.y()) && q.x() < a.x() + (q.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
}

/// Signed distance from q to the closed polygon (negative inside, by the even-odd rule), every
/// edge read. The nearest edge is found by squared distance: one square root per point.
double polygonDistance(const std::vector<openvdb::Vec2d>& polygon, const openvdb::Vec2d& q)
{
    double nearest2 = std::numeric_limits<double>::infinity();
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        nearest2 = std::min(nearest2, segmentDistance2(polygon[j], polygon[i], q));
        inside ^= crossesRay(polygon[j], polygon[i], q);
    }
    const double nearest = std::sqrt(nearest2);
    return inside ? -nearest : nearest;
}

/// The points farther than `tolerance` from the last one kept: an outline within `tolerance` of
/// the polygon's, in one pass, whose points are at least `tolerance` apart.
std::vector<openvdb::Vec2d> spacedPoints(const std::vector<openvdb::Vec2d>& polygon, double tolerance)
{
    std::vector<openvdb::Vec2d> kept{polygon.front()};
    for (const openvdb::Vec2d& p : polygon)
        if ((p - kept.back()).lengthSqr() > tolerance * tolerance) kept.push_back(p);
    return kept.size() >= 3 ? kept : polygon;
}

/// The closed polygon within `tolerance` of its outline with fewer points: first spaced
/// (spacedPoints, half the tolerance), then the points dropped that lie within the other half of
/// the chord replacing them (Douglas-Peucker, split first at the point farthest from the first).
/// The spacing bounds Douglas-Peucker's work by the outline's length, whatever the points' count.
std::vector<openvdb::Vec2d> simplifiedPolygon(const std::vector<openvdb::Vec2d>& drawn, double tolerance)
{
    const std::vector<openvdb::Vec2d> polygon = spacedPoints(drawn, 0.5 * tolerance);
    tolerance *= 0.5;
    const std::size_t n = polygon.size();
    std::size_t far = 0;
    for (std::size_t i = 1; i < n; ++i)
        if ((polygon[i] - polygon[0]).lengthSqr() > (polygon[far] - polygon[0]).lengthSqr()) far = i;
    if (n < 4 || far == 0) return polygon;
    std::vector<bool> kept(n, false);
    kept[0] = kept[far] = true;
    std::vector<std::pair<std::size_t, std::size_t>> spans{{0, far}, {far, n}};  // n stands for 0 again
    const double tolerance2 = tolerance * tolerance;
    while (!spans.empty()) {
        const auto [from, to] = spans.back();
        spans.pop_back();
        const openvdb::Vec2d &a = polygon[from], &b = polygon[to % n];
        double worst = tolerance2;
        std::size_t split = from;
        for (std::size_t i = from + 1; i < to; ++i) {
            const double d2 = segmentDistance2(a, b, polygon[i]);
            if (d2 > worst) worst = d2, split = i;
        }
        if (split == from) continue;
        kept[split] = true;
        spans.push_back({from, split});
        spans.push_back({split, to});
    }
    std::vector<openvdb::Vec2d> result;
    for (std::size_t i = 0; i < n; ++i)
        if (kept[i]) result.push_back(polygon[i]);
    return result.size() >= 3 ? result : polygon;
}

/// `p` mirrored across the planes x = 0, y = 0, z = 0 that bits 0, 1, 2 of `m` pick.
openvdb::Vec3d mirrored(const openvdb::Vec3d& p, int m)
{
    return {m & 1 ? -p.x() : p.x(), m & 2 ? -p.y() : p.y(), m & 4 ? -p.z() : p.z()};
}

/// The prism's distance at `world` (mirrors, slab, perspective), its polygon's read by
/// `across(q, capPlane)`: q in the view plane, the cap in the plane's units there.
template <typename Across>
double sweptDistance(const ViewPrism& prism, const openvdb::Vec3d& world, const Across& across, double capWorld)
{
    double best = std::numeric_limits<double>::infinity();
    for (int m = 0; m < 8; ++m) {
        if (((m & 1) && !prism.mirror[0]) || ((m & 2) && !prism.mirror[1]) || ((m & 4) && !prism.mirror[2])) continue;
        const openvdb::Vec3d v = prism.viewFromWorld.transform(mirrored(world, m));
        const double depth = -v.z();
        const double slab = std::max(prism.nearDepth - depth, depth - prism.farDepth);
        double side;
        if (!prism.perspective) {
            side = across({v.x(), v.y()}, capWorld);
        } else if (depth > 1e-9) {
            side = across({v.x() / depth, v.y() / depth}, capWorld / depth) * depth;
        } else {
            side = -depth + 1e-9;  // behind the eye: outside, by about the distance to its plane
        }
        best = std::min(best, std::max(side, slab));
    }
    return best;
}

}  // namespace

/// The polygon's edges binned on a grid of square cells, by rows (to mark once whether each
/// cell's centre is inside) and by cells (for the edges near a point, and a point's even-odd
/// answer from its cell's centre). At most kMaxCells cells a side: a half-plane's polygon reaches
/// far beyond what is cut.
class EdgeBins {
public:
    EdgeBins(const std::vector<openvdb::Vec2d>& polygon, double cell)
    {
        openvdb::Vec2d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (const openvdb::Vec2d& p : polygon) lo = minComponent(lo, p), hi = maxComponent(hi, p);
        mOrigin = lo;
        // Cells finer than the cap only where the edges are: a polygon of few long edges reads
        // them faster in a few wide cells.
        double outline = 0.0;
        for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
            outline += (polygon[i] - polygon[j]).length();
        const double perCap = std::clamp(cell * double(polygon.size()) / std::max(outline, 1e-300), 1.0, kCellsPerCap);
        mCell = std::max({cell / perCap, (hi.x() - lo.x()) / kMaxCells, (hi.y() - lo.y()) / kMaxCells, 1e-12});
        mColumns = int((hi.x() - lo.x()) / mCell) + 1;
        mRows = int((hi.y() - lo.y()) / mCell) + 1;
        for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
            mEdges.emplace_back(polygon[j], polygon[i]);
        fileEdges();
        markCentres();
        mRowEdges.clear();
    }

    /// The signed distance from q to the polygon where it is under `cap`; else at least `cap`, of
    /// the right sign (even-odd).
    /// The nearest edge is looked for in rings of cells around q's, stopping at the first ring
    /// farther than the nearest edge found: near a lasso of many short edges, a few cells' edges.
    double distance(const openvdb::Vec2d& q, double cap) const
    {
        const bool inside = isInside(q);
        double nearest2 = cap * cap;
        const int rings = int(std::ceil(cap / mCell)) + 1;
        if (mEdges.size() <= kFewEdges) {
            for (std::size_t e = 0; e < mEdges.size(); ++e) nearest2 = std::min(nearest2, edgeDistance2(e, q));
        } else {
            const int r0 = row(q.y()), c0 = column(q.x());
            for (int k = 0; k <= rings; ++k) {
                const double reach = std::max(k - 1, 0) * mCell;  // every cell of ring k is at least this far
                if (reach * reach >= nearest2) break;
                forRing(r0, c0, k, [&](std::size_t cell) {
                    for (std::uint32_t i = mCellStart[cell]; i < mCellStart[cell + 1]; ++i)
                        nearest2 = std::min(nearest2, edgeDistance2(mCellEdges[i], q));
                });
            }
        }
        const double nearest = std::sqrt(nearest2);
        return inside ? -nearest : nearest;
    }

private:
    static constexpr double kMaxCells = 2048.0;
    /// A polygon this small is read whole: cheaper than visiting cells.
    static constexpr std::size_t kFewEdges = 8;
    /// Cells at most across the distance a point needs exactly (its cap): small enough that a cell
    /// near a lasso of short edges holds few, few enough that a point far from it visits few.
    static constexpr double kCellsPerCap = 4.0;

    int column(double x) const
    {
        return int(std::clamp(std::floor((x - mOrigin.x()) / mCell), -1.0, double(mColumns)));
    }
    int row(double y) const { return int(std::clamp(std::floor((y - mOrigin.y()) / mCell), -1.0, double(mRows))); }

    double edgeDistance2(std::size_t e, const openvdb::Vec2d& q) const
    {
        return segmentDistance2(mEdges[e].first, mEdges[e].second, q);
    }

    openvdb::Vec2d centre(int r, int c) const { return mOrigin + openvdb::Vec2d(c + 0.5, r + 0.5) * mCell; }

    /// Whether q is inside (even-odd): its cell's centre's answer, changed by each edge of the
    /// cell crossed on the way from the centre to q, across then up. So a point costs the edges
    /// of its cell, not of its row (a lasso of 100,000 points has thousands in a row).
    bool isInside(const openvdb::Vec2d& q) const
    {
        const int r = row(q.y()), c = column(q.x());
        if (r < 0 || r >= mRows || c < 0 || c >= mColumns) return false;  // beyond the polygon's box
        const std::size_t cell = std::size_t(r) * std::size_t(mColumns) + std::size_t(c);
        const openvdb::Vec2d o = centre(r, c);
        bool inside = mCentreInside[cell] != 0;
        for (std::uint32_t i = mCellStart[cell]; i < mCellStart[cell + 1]; ++i) {
            const openvdb::Vec2d &a = mEdges[mCellEdges[i]].first, &b = mEdges[mCellEdges[i]].second;
            // Across, at the centre's y: the +x ray's crossings between the two x (crossesRay's rule).
            if ((a.y() > o.y()) != (b.y() > o.y())) {
                const double x = a.x() + (o.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
                inside ^= x > std::min(o.x(), q.x()) && x <= std::max(o.x(), q.x());
            }
            // Then up, at q's x: the +y ray's crossings between the two y.
            if ((a.x() > q.x()) != (b.x() > q.x())) {
                const double y = a.y() + (q.x() - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
                inside ^= y > std::min(o.y(), q.y()) && y <= std::max(o.y(), q.y());
            }
        }
        return inside;
    }

    /// Whether each cell's centre is inside: per row, the crossings of the +x ray at the centres'
    /// y, sorted, counted past each centre.
    void markCentres()
    {
        mCentreInside.assign(std::size_t(mRows) * std::size_t(mColumns), 0);
        std::vector<double> crossings;
        for (int r = 0; r < mRows; ++r) {
            const double y = centre(r, 0).y();
            crossings.clear();
            for (const std::uint32_t e : mRowEdges[std::size_t(r)]) {
                const openvdb::Vec2d &a = mEdges[e].first, &b = mEdges[e].second;
                if ((a.y() > y) != (b.y() > y))
                    crossings.push_back(a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
            }
            std::sort(crossings.begin(), crossings.end());
            for (int c = 0; c < mColumns; ++c) {
                const auto past =
                    crossings.end() - std::upper_bound(crossings.begin(), crossings.end(), centre(r, c).x());
                mCentreInside[std::size_t(r) * std::size_t(mColumns) + std::size_t(c)] = std::uint8_t(past % 2);
            }
        }
    }

    /// The cells of the square ring k around cell (r0, c0) that lie on the grid.
    template <typename Visit>
    void forRing(int r0, int c0, int k, const Visit& visit) const
    {
        const auto at = [&](int r, int c) {
            if (r >= 0 && r < mRows && c >= 0 && c < mColumns)
                visit(std::size_t(r) * std::size_t(mColumns) + std::size_t(c));
        };
        if (k == 0) return at(r0, c0);
        for (int c = c0 - k; c <= c0 + k; ++c) at(r0 - k, c), at(r0 + k, c);
        for (int r = r0 - k + 1; r <= r0 + k - 1; ++r) at(r, c0 - k), at(r, c0 + k);
    }

    /// Files every edge under the rows its y-range meets and, counted first and then stored in one
    /// array, the cells it passes.
    void fileEdges()
    {
        mRowEdges.assign(std::size_t(mRows), {});
        mCellStart.assign(std::size_t(mRows) * std::size_t(mColumns) + 1, 0);
        for (std::size_t e = 0; e < mEdges.size(); ++e)
            forCells(mEdges[e].first, mEdges[e].second, [&](std::size_t cell) { ++mCellStart[cell + 1]; });
        for (std::size_t cell = 1; cell < mCellStart.size(); ++cell) mCellStart[cell] += mCellStart[cell - 1];
        mCellEdges.resize(mCellStart.back());
        std::vector<std::uint32_t> filled(mCellStart.begin(), mCellStart.end() - 1);
        for (std::size_t e = 0; e < mEdges.size(); ++e) {
            const openvdb::Vec2d &a = mEdges[e].first, &b = mEdges[e].second;
            forCells(a, b, [&](std::size_t cell) { mCellEdges[filled[cell]++] = std::uint32_t(e); });
            const int r0 = std::max(row(std::min(a.y(), b.y())), 0),
                      r1 = std::min(row(std::max(a.y(), b.y())), mRows - 1);
            for (int r = r0; r <= r1; ++r) mRowEdges[std::size_t(r)].push_back(std::uint32_t(e));
        }
    }

    /// The cells edge (a, b) passes (a superset: per row it meets, its x-range there).
    template <typename Visit>
    void forCells(const openvdb::Vec2d& a, const openvdb::Vec2d& b, const Visit& visit) const
    {
        const int r0 = std::max(row(std::min(a.y(), b.y())), 0), r1 = std::min(row(std::max(a.y(), b.y())), mRows - 1);
        for (int r = r0; r <= r1; ++r) {
            // The part of the edge within the row's band of y: its x-range, clipped.
            const double y0 = mOrigin.y() + r * mCell, y1 = y0 + mCell;
            double x0 = a.x(), x1 = b.x();
            if (b.y() != a.y()) {
                const auto xAt = [&](double y) { return a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()); };
                const double ya = std::clamp(y0, std::min(a.y(), b.y()), std::max(a.y(), b.y()));
                const double yb = std::clamp(y1, std::min(a.y(), b.y()), std::max(a.y(), b.y()));
                x0 = xAt(ya), x1 = xAt(yb);
            }
            const int c0 = std::max(column(std::min(x0, x1)), 0), c1 = std::min(column(std::max(x0, x1)), mColumns - 1);
            for (int c = c0; c <= c1; ++c) visit(std::size_t(r) * std::size_t(mColumns) + std::size_t(c));
        }
    }

    static openvdb::Vec2d minComponent(const openvdb::Vec2d& a, const openvdb::Vec2d& b)
    {
        return {std::min(a.x(), b.x()), std::min(a.y(), b.y())};
    }
    static openvdb::Vec2d maxComponent(const openvdb::Vec2d& a, const openvdb::Vec2d& b)
    {
        return {std::max(a.x(), b.x()), std::max(a.y(), b.y())};
    }

    std::vector<std::pair<openvdb::Vec2d, openvdb::Vec2d>> mEdges;
    openvdb::Vec2d mOrigin{0.0};
    double mCell = 1.0;
    int mColumns = 1, mRows = 1;
    std::vector<std::vector<std::uint32_t>> mRowEdges;  // while the centres are marked
    std::vector<std::uint32_t> mCellStart, mCellEdges;  // cell c's edges: mCellEdges[mCellStart[c] ..]
    std::vector<std::uint8_t> mCentreInside;            // per cell
};

namespace {

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
    return sweptDistance(
        *this, world, [this](const openvdb::Vec2d& q, double) { return polygonDistance(polygon, q); },
        std::numeric_limits<double>::infinity());
}

PrismDistance::PrismDistance(const ViewPrism& prism, double capWorld, const openvdb::BBoxd& box, double toleranceWorld)
    : mPrism(prism), mCap(capWorld)
{
    // Cells as wide as the cap where it is narrowest in the view plane: at the farthest depth of
    // the box's corners and their mirror images.
    double farthest = 1e-9;
    for (int corner = 0; corner < 8; ++corner) {
        const openvdb::Vec3d p(corner & 1 ? box.max().x() : box.min().x(), corner & 2 ? box.max().y() : box.min().y(),
                               corner & 4 ? box.max().z() : box.min().z());
        for (int m = 0; m < 8; ++m) farthest = std::max(farthest, -prism.viewFromWorld.transform(mirrored(p, m)).z());
    }
    const double perWorld = prism.perspective ? 1.0 / farthest : 1.0;  // view-plane units at that depth
    if (toleranceWorld > 0.0) mPrism.polygon = simplifiedPolygon(prism.polygon, toleranceWorld * perWorld);
    mBins = std::make_shared<const EdgeBins>(mPrism.polygon, capWorld * perWorld);
}

double PrismDistance::operator()(const openvdb::Vec3d& world) const
{
    return sweptDistance(
        mPrism, world, [this](const openvdb::Vec2d& q, double cap) { return mBins->distance(q, cap); }, mCap);
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
    // Exact within a band and a leaf's diagonal (what the rasterizer reads), a sign beyond.
    const double leafDiagonal = std::sqrt(3.0) * 8.0 * field.voxelSize();
    const PrismDistance distance(prism, 2.0 * (field.grid().background() + leafDiagonal), reach,
                                 kPolygonToleranceVoxels * field.voxelSize());
    AnalyticSdf sdf;
    sdf.distance = [&](const openvdb::Vec3d& p) { return std::max(distance(p), boxDistance(reach, p)); };
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
