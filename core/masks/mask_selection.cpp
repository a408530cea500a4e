// SPDX-License-Identifier: Apache-2.0
#include "core/masks/mask_selection.h"

#include "core/base/enum_names.h"
#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/central_difference.h"
#include "core/field/mean_curvature.h"
#include "core/masks/mask_edit.h"
#include "core/solids/islands.h"
#include "core/solids/wall_thickness.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

constexpr EnumNames<MaskSelectionKind, 4> kKinds{{{MaskSelectionKind::Prism, "prism"},
                                                  {MaskSelectionKind::Cavity, "cavity"},
                                                  {MaskSelectionKind::Thin, "thin"},
                                                  {MaskSelectionKind::Island, "island"}}};

/// The degree a voxel is selected, in [0, 1].
using Degree = std::function<double(const openvdb::Coord& ijk, const MaskSite& site)>;

/// A selected region and the leaves it may reach.
struct Selected {
    std::vector<openvdb::Coord> leaves;
    Degree degree;
};

void requirePositive(double value, const char* what)
{
    if (!(value > 0.0) || !std::isfinite(value))
        throw InputError(std::string("a mask selection's ") + what + " must be a positive number (got " +
                         formatNumber(value) + ")");
}

/// Inside the prism: all or nothing, so that erasing with the same gesture frees what it masked.
Selected prismSelection(const FieldImage& field, const ViewPrism& prism)
{
    validatePrism(prism);
    const double h = field.voxelSize();
    // A leaf's voxels lie within its half diagonal of its centre, their closest points a band
    // farther; the margin doubles that for a perspective prism, whose distance is not exact.
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * 8.0 * h;
    const double margin = 2.0 * (halfDiagonal + field.grid().background() + h);
    openvdb::CoordBBox leafBox;
    field.grid().tree().evalLeafBoundingBox(leafBox);
    openvdb::BBoxd box = field.grid().transform().indexToWorld(leafBox);
    box.expand(margin);
    const PrismDistance distance(prism, 2.0 * margin, box, kPolygonToleranceVoxels * h);
    Selected selected;
    for (const openvdb::Coord& origin : maskDomain(field)) {
        const openvdb::Vec3d centre = field.grid().transform().indexToWorld(origin.asVec3d() + openvdb::Vec3d(3.5));
        if (distance(centre) <= margin) selected.leaves.push_back(origin);
    }
    selected.degree = [distance](const openvdb::Coord& ijk, const MaskSite& site) {
        return distance(site.footWorld(ijk)) <= 0.0 ? 1.0 : 0.0;
    };
    return selected;
}

/// Where the band curves inwards: s = -kappa r / 2, kappa measured at the voxel nearest the
/// closest surface point with differences two voxels wide (second differences one voxel wide
/// amplify the field's error beyond a small curvature's size; the wide stencil stays within the
/// band from there).
Selected cavitySelection(const FieldImage& field, double creaseRadius)
{
    requirePositive(creaseRadius, "crease radius");
    const double invWide = 0.5 / field.voxelSize();
    const float band = field.grid().background();
    const openvdb::math::Transform& xform = field.grid().transform();
    return {maskDomain(field), [=, &xform](const openvdb::Coord& ijk, const MaskSite& site) {
                const auto& acc = site.surface();
                if (std::abs(acc.getValue(ijk)) >= band) return 0.0;
                const openvdb::Coord foot = openvdb::Coord::round(xform.worldToIndex(site.footWorld(ijk)));
                const double kappa = curvatureNormGrad(
                    [&](int x, int y, int z) { return acc.getValue(foot.offsetBy(2 * x, 2 * y, 2 * z)); }, 0, 0, 0,
                    invWide);
                return std::clamp(-0.5 * kappa * creaseRadius, 0.0, 1.0);
            }};
}

/// Where the wall under the closest surface point is thinner than `thickness`.
Selected thinSelection(const FieldImage& field, double thickness)
{
    requirePositive(thickness, "thickness");
    const float band = field.grid().background();
    const openvdb::FloatGrid& grid = field.grid();
    return {maskDomain(field), [&grid, band, thickness](const openvdb::Coord& ijk, const MaskSite& site) {
                const auto& acc = site.surface();
                const openvdb::Vec3d difference = centralDifferenceAt(acc, ijk);
                if (std::abs(acc.getValue(ijk)) >= band || difference.length() < 1e-12) return 0.0;
                const std::optional<double> wall =
                    wallThicknessAt(grid, site.footWorld(ijk), difference.unitSafe(), thickness);
                return wall && *wall < thickness ? 1.0 : 0.0;
            }};
}

/// The island nearest `point` (within a band): its voxels, inside or in its band.
Selected islandSelection(const FieldImage& field, const openvdb::Vec3d& point)
{
    std::vector<Island> islands = findIslands(field);
    // Within two voxels: the band's edge (three) reads as far from every island alike.
    const double reach = 2.0 * field.voxelSize();
    const int index = islandAt(islands, point, reach);
    if (index < 0) throw InputError("no island lies within " + formatNumber(reach) + " of the point to mask");
    openvdb::FloatGrid::Ptr island = islands[std::size_t(index)].grid;
    Selected selected;
    for (auto leaf = island->tree().cbeginLeaf(); leaf; ++leaf) selected.leaves.push_back(leaf->origin());
    const float band = island->background();
    selected.degree = [island, band](const openvdb::Coord& ijk, const MaskSite&) {
        return island->tree().getValue(ijk) < band ? 1.0 : 0.0;
    };
    return selected;
}

Selected select(const FieldImage& field, const MaskSelection& selection)
{
    switch (selection.kind) {
    case MaskSelectionKind::Prism: return prismSelection(field, selection.prism);
    case MaskSelectionKind::Cavity: return cavitySelection(field, selection.creaseRadiusWorld);
    case MaskSelectionKind::Thin: return thinSelection(field, selection.thicknessWorld);
    case MaskSelectionKind::Island: return islandSelection(field, selection.point);
    }
    return {};
}

}  // namespace

MaskSelectionKind maskSelectionFromName(const std::string& name)
{
    return enumFromName(kKinds, name, "mask selection");
}

const char* maskSelectionName(MaskSelectionKind kind) { return enumName(kKinds, kind); }

DirtyRegion applyMaskSelection(FieldImage& field, const MaskSelection& selection, LeafJournal* journal)
{
    const Selected selected = select(field, selection);
    const bool erase = selection.erase;
    return rewriteMask(field, selected.leaves, journal, [&](const openvdb::Coord& ijk, const MaskSite& site) {
        const double s = selected.degree(ijk, site), m = site.mask(ijk);
        return erase ? std::min(m, 1.0 - s) : std::max(m, s);
    });
}

}  // namespace sculpt
