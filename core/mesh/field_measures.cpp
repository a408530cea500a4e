// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/field_measures.h"

#include "core/base/union_find.h"
#include "core/mesh/incremental_mesher.h"
#include "core/mesh/surface_statistics.h"

#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_reduce.h>

#include <vector>

namespace sculpt {

namespace {

using LeafRange = openvdb::tree::LeafManager<const openvdb::FloatTree>::LeafRange;

/// Index-space bounding box of the linear zero crossings between face-adjacent voxels.
struct CrossingBounds {
    const openvdb::FloatTree* tree;
    openvdb::BBoxd box;  // default-constructed: empty (min > max)

    CrossingBounds(const openvdb::FloatTree& t) : tree(&t) {}
    CrossingBounds(const CrossingBounds& other, tbb::split) : tree(other.tree) {}

    void operator()(const LeafRange& range)
    {
        openvdb::tree::ValueAccessor<const openvdb::FloatTree> acc(*tree);
        for (auto leaf = range.begin(); leaf; ++leaf) {
            for (auto it = leaf->cbeginValueOn(); it; ++it) {
                if (*it >= 0.0f) continue;
                addCrossings(acc, it.getCoord(), *it);
            }
        }
    }

    void addCrossings(openvdb::tree::ValueAccessor<const openvdb::FloatTree>& acc, const openvdb::Coord& ijk,
                      float inside)
    {
        for (int axis = 0; axis < 3; ++axis) {
            for (int step : {-1, 1}) {
                openvdb::Coord n = ijk;
                n[axis] += step;
                const float outside = acc.getValue(n);
                if (outside < 0.0f) continue;
                openvdb::Vec3d p = ijk.asVec3d();
                p[axis] += step * double(inside) / (double(inside) - double(outside));
                box.expand(p);
            }
        }
    }

    void join(const CrossingBounds& other) { box.expand(other.box); }
};

/// The number of shells of a welded mesh: sets of triangles connected through shared vertices.
int countShells(const TriangleMesh& mesh)
{
    UnionFind sets(mesh.positions.size());
    for (const auto& t : mesh.triangles) {
        sets.join(t[1], t[0]);
        sets.join(t[2], t[0]);
    }
    return int(sets.count());
}

/// Volume (divergence theorem), area, V - E + F and shells of our welded mesh. It is closed
/// (E = 3F/2), so the Euler characteristic is exact, unlike the Gauss-Bonnet integral of
/// LevelSetMeasure, which creases (CSG, carving) throw off; and volume and area are those of the
/// surface the user exports, whatever |grad phi| is (LevelSetMeasure assumes 1: imported scans
/// keep the scanner's crossings, where it is not). Shells are counted on the mesh too: voxel
/// connectivity joins shells that come within a voxel (a bubble just under the surface).
void measureMesh(const FieldImage& field, FieldMeasures& m)
{
    const TriangleMesh mesh = meshLevelSet(field);
    double volume = 0.0, area = 0.0;
    for (const auto& t : mesh.triangles) {
        const auto at = [&](std::uint32_t i) {
            const auto& p = mesh.positions[i];
            return openvdb::Vec3d(p[0], p[1], p[2]);
        };
        const openvdb::Vec3d a = at(t[0]), b = at(t[1]), c = at(t[2]);
        volume += a.dot(b.cross(c)) / 6.0;
        area += 0.5 * (b - a).cross(c - a).length();
    }
    m.volume = volume;
    m.area = area;
    m.eulerCharacteristic = int(std::int64_t(mesh.positions.size()) - std::int64_t(mesh.triangles.size()) / 2);
    m.components = countShells(mesh);
}

}  // namespace

FieldMeasures measureField(const FieldImage& field)
{
    const auto& grid = field.grid();
    FieldMeasures m;
    m.voxelSize = field.voxelSize();
    m.halfWidthVoxels = field.halfWidthVoxels();
    m.activeVoxels = grid.activeVoxelCount();
    m.memoryBytes = grid.memUsage();

    openvdb::tree::LeafManager<const openvdb::FloatTree> leaves(grid.tree());
    CrossingBounds bounds(grid.tree());
    tbb::parallel_reduce(leaves.leafRange(), bounds);
    if (bounds.box.isSorted()) {
        m.bboxMin = grid.transform().indexToWorld(bounds.box.min());
        m.bboxMax = grid.transform().indexToWorld(bounds.box.max());
    }

    measureMesh(field, m);
    return m;
}

MeshVolumeArea meshVolumeArea(const FieldImage& field)
{
    IncrementalMesher mesher;
    mesher.rebuild(field);
    SurfaceStatistics statistics;  // per-block sums: the triangles partition the closed surface
    statistics.update(mesher);
    return {statistics.volume(), statistics.area()};
}

}  // namespace sculpt
