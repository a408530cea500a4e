// SPDX-License-Identifier: Apache-2.0
#include "core/solids/hollow.h"

#include "core/base/enum_names.h"
#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/base/union_find.h"
#include "core/field/csg_combine.h"
#include "core/local/capsule.h"
#include "core/local/local_patch.h"
#include "core/mesh/incremental_mesher.h"
#include "core/solids/wall_thickness.h"

#include <openvdb/tools/LevelSetRebuild.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace sculpt {

namespace {

constexpr EnumNames<ShellSide, 3> kSides{
    {{ShellSide::Inside, "inside"}, {ShellSide::Medial, "medial"}, {ShellSide::Outside, "outside"}}};

constexpr double kMaxThicknessVoxels = 1000.0;

void validate(const HollowOptions& o, double voxelSize)
{
    if (!(o.thicknessWorld > 0.0) || !std::isfinite(o.thicknessWorld))
        throw InputError("the shell's thickness must be a positive number (got " + formatNumber(o.thicknessWorld) +
                         ")");
    if (!(o.closingWorld >= 0.0) || !std::isfinite(o.closingWorld))
        throw InputError("the closing distance must be zero or more (got " + formatNumber(o.closingWorld) + ")");
    if ((o.thicknessWorld + o.closingWorld) / voxelSize > kMaxThicknessVoxels)
        throw InputError("a shell of " + formatNumber(o.thicknessWorld) + " is over " +
                             formatNumber(kMaxThicknessVoxels) + " voxels thick: choose a thinner shell",
                         Remedy::CoarserVoxelSize);
}

/// The level set at `iso` of `grid` (whose band reaches it), with a band `outsideVoxels` out and
/// `insideVoxels` in: OpenVDB's levelSetRebuild (meshes the iso-surface, voxelizes it again).
openvdb::FloatGrid::Ptr rebuiltAt(const openvdb::FloatGrid& grid, double iso, double outsideVoxels, double insideVoxels)
{
    return openvdb::tools::levelSetRebuild(grid, float(iso), float(outsideVoxels), float(insideVoxels));
}

/// The lowest point along `up` of each cavity: each connected part of the cavity's mesh (a part
/// is one cavity's wall), among its vertices within half a voxel of its lowest, the one nearest
/// their middle (a flat floor drains from its centre, not a corner).
std::vector<openvdb::Vec3d> bottomsOf(const openvdb::FloatGrid::Ptr& cavity, const openvdb::Vec3d& up)
{
    const TriangleMesh mesh = meshLevelSet(FieldImage(cavity));
    UnionFind parts(mesh.positions.size());
    for (const auto& t : mesh.triangles) parts.join(t[0], t[1]), parts.join(t[1], t[2]);
    const auto point = [&](std::size_t v) {
        return openvdb::Vec3d(mesh.positions[v][0], mesh.positions[v][1], mesh.positions[v][2]);
    };
    std::map<std::uint32_t, double> lowest;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const auto [at, fresh] = lowest.emplace(parts.find(v), point(v).dot(up));
        if (!fresh) at->second = std::min(at->second, point(v).dot(up));
    }
    const double h = cavity->transform().voxelSize()[0];
    std::map<std::uint32_t, std::vector<openvdb::Vec3d>> floors;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
        if (point(v).dot(up) <= lowest[parts.find(v)] + 0.5 * h) floors[parts.find(v)].push_back(point(v));
    std::vector<openvdb::Vec3d> bottoms;
    for (const auto& [part, floor] : floors) {
        openvdb::Vec3d middle(0.0);
        for (const openvdb::Vec3d& p : floor) middle += p;
        middle /= double(floor.size());
        bottoms.push_back(*std::min_element(floor.begin(), floor.end(), [&](const auto& a, const auto& b) {
            return (a - middle).lengthSqr() < (b - middle).lengthSqr();
        }));
    }
    return bottoms;
}

}  // namespace

ShellSide shellSideFromName(const std::string& name) { return enumFromName(kSides, name, "shell side"); }

HollowResult hollow(const FieldImage& field, const HollowOptions& o, const openvdb::Vec3d& up, const Progress& progress)
{
    validate(o, field.voxelSize());
    const double t = o.thicknessWorld, c = o.closingWorld, w = field.halfWidthVoxels();
    const openvdb::Vec3d upward = up.length() > 0.0 ? up.unitSafe() : openvdb::Vec3d(0, 0, 1);
    // The surfaces bounding the shell: `outer` (kept as the field where it can be) and the cavity.
    const bool inside = o.side == ShellSide::Inside, outside = o.side == ShellSide::Outside;
    const double inner = inside ? t : o.side == ShellSide::Medial ? t / 2 : 0.0;   // cavity depth
    const double outer = outside ? t : o.side == ShellSide::Medial ? t / 2 : 0.0;  // outer wall's rise
    const double h = field.voxelSize();
    // The surface's distances behind both walls (and a voxel more), then each wall as a band.
    const openvdb::FloatGrid::Ptr wide = rebuiltAt(field.grid(), 0.0, w + (outer + h) / h, w + (inner + c + h) / h);
    report(progress, 0.4);
    openvdb::FloatGrid::Ptr cavity =
        inner > 0.0 ? rebuiltAt(*wide, -(inner + c), w + c / h, w) : field.grid().deepCopy();
    if (c > 0.0 && inner > 0.0) cavity = rebuiltAt(*cavity, c, w, w);
    report(progress, 0.7);
    openvdb::FloatGrid::Ptr shell = outer > 0.0 ? rebuiltAt(*wide, outer, w, w) : field.grid().deepCopy();
    const std::vector<openvdb::Vec3d> bottoms = bottomsOf(cavity, upward);
    combineWhole(*shell, *cavity, CsgOperation::Difference);
    shell->setName(field.grid().getName());
    report(progress, 1.0);
    return {FieldImage(shell, field.units()), bottoms};
}

std::vector<DrainHole> drainHolesUnder(const std::vector<openvdb::Vec3d>& bottoms, const openvdb::Vec3d& up,
                                       double wallWorld, double radiusWorld)
{
    const openvdb::Vec3d down = -(up.length() > 0.0 ? up.unitSafe() : openvdb::Vec3d(0, 0, 1));
    std::vector<DrainHole> holes;
    // From inside the cavity to beyond the wall's outside, with a radius to spare at each end.
    for (const openvdb::Vec3d& bottom : bottoms)
        holes.push_back({bottom - down * radiusWorld, bottom + down * (wallWorld + 2.0 * radiusWorld), radiusWorld});
    return holes;
}

std::optional<DrainHole> drainHoleAt(const FieldImage& field, const openvdb::Vec3d& surfacePoint,
                                     const openvdb::Vec3d& normal, double radiusWorld, double farthestWorld)
{
    const std::optional<double> wall = wallThicknessAt(field.grid(), surfacePoint, normal, farthestWorld);
    if (!wall) return std::nullopt;
    return DrainHole{surfacePoint + normal * radiusWorld, surfacePoint - normal * (*wall + radiusWorld), radiusWorld};
}

void cutDrainHoles(FieldImage& field, const std::vector<DrainHole>& holes, LeafJournal* journal)
{
    for (const DrainHole& hole : holes) {
        if (!(hole.radiusWorld > 0.0) || !std::isfinite(hole.radiusWorld))
            throw InputError("a drain hole's radius must be a positive number (got " + formatNumber(hole.radiusWorld) +
                             ")");
        for (const openvdb::Vec3d& end : {hole.from, hole.to})
            if (!std::isfinite(end.x()) || !std::isfinite(end.y()) || !std::isfinite(end.z()))
                throw InputError("a drain hole's end is not finite");
    }
    for (const DrainHole& hole : holes) {
        const Capsule capsule{hole.from, hole.to, hole.radiusWorld};
        const Capsule reach = capsule.grownBy(field.grid().background());
        LocalPatch patch(field, reach);
        patch.combineVoxels(reach, field.grid().background(), [&](const openvdb::Vec3d& world, float phi) {
            return std::max(double(phi), capsule.radius - capsule.axisDistance(world));
        });
        patch.commit(field, journal);
    }
}

}  // namespace sculpt
