// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/incremental_mesher.h"

#include "core/mesh/block_mesher.h"
#include "core/mesh/mesh_welder.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <set>

namespace sculpt {

namespace {

/// Block origins o (multiples of B) with lo <= o <= hi on every axis.
void addBlocksBetween(const openvdb::Coord& lo, const openvdb::Coord& hi, int B, std::set<openvdb::Coord>& out)
{
    const openvdb::Coord first(floorToMultiple(lo.x() + B - 1, B), floorToMultiple(lo.y() + B - 1, B),
                               floorToMultiple(lo.z() + B - 1, B));
    for (int x = first.x(); x <= hi.x(); x += B)
        for (int y = first.y(); y <= hi.y(); y += B)
            for (int z = first.z(); z <= hi.z(); z += B) out.insert(openvdb::Coord(x, y, z));
}

/// Every block that has a cell reading a voxel of some leaf: only those can hold surface.
std::vector<openvdb::Coord> blocksWithLeaves(const openvdb::FloatTree& tree, int B)
{
    std::set<openvdb::Coord> origins;
    for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf) {
        // Cells with minimum corner in [leaf - 1, leaf + 7] read the leaf.
        const openvdb::Coord o = leaf->origin();
        addBlocksBetween(o.offsetBy(-B), o.offsetBy(7), B, origins);
    }
    return {origins.begin(), origins.end()};
}

/// Blocks whose samples [o - 1, o + B + 1] overlap a dirty leaf [L, L + 7].
std::vector<openvdb::Coord> blocksReading(const DirtyRegion& dirty, int B)
{
    std::set<openvdb::Coord> origins;
    for (const openvdb::Coord& leaf : dirty.leafOrigins()) {
        addBlocksBetween(leaf.offsetBy(-B - 1), leaf.offsetBy(8), B, origins);
    }
    return {origins.begin(), origins.end()};
}

/// Edge keys pack index coordinates in 20 bits each: refuse boxes beyond that range.
void requireKeyRange(const openvdb::CoordBBox& box)
{
    for (int axis = 0; axis < 3 && !box.empty(); ++axis) {
        if (box.min()[axis] < -kMaxIndexCoordinate || box.max()[axis] > kMaxIndexCoordinate) {
            throw std::out_of_range("the field spans more than 2^20 voxels: too large to mesh");
        }
    }
}

}  // namespace

IncrementalMesher::IncrementalMesher(int blockVoxels) : mBlockVoxels(blockVoxels)
{
    BlockMesher::validateBlockSize(blockVoxels);
}

void IncrementalMesher::rebuild(const FieldImage& field, const Progress& progress)
{
    openvdb::CoordBBox box;
    field.grid().tree().evalLeafBoundingBox(box);
    requireKeyRange(box);
    const auto origins = blocksWithLeaves(field.grid().tree(), mBlockVoxels);
    std::map<openvdb::Coord, BlockMesh> previous;
    previous.swap(mBlocks);
    remesh(field, origins, progress);
    std::vector<openvdb::Coord> dropped;
    for (const auto& [origin, mesh] : previous) {
        if (!mBlocks.count(origin)) dropped.push_back(origin);
    }
    logChanges(std::move(dropped));
}

std::size_t IncrementalMesher::update(const FieldImage& field, const DirtyRegion& dirty)
{
    openvdb::CoordBBox box;  // of the dirty leaves only: the rest was checked when meshed
    for (const openvdb::Coord& origin : dirty.leafOrigins()) box.expand(openvdb::CoordBBox::createCube(origin, 8));
    requireKeyRange(box);
    const auto origins = blocksReading(dirty, mBlockVoxels);
    if (!origins.empty()) remesh(field, origins);  // nothing dirty: the same version
    return origins.size();
}

void IncrementalMesher::remesh(const FieldImage& field, const std::vector<openvdb::Coord>& origins,
                               const Progress& progress)
{
    ++mVersion;
    std::vector<BlockMesh> meshes(origins.size());
    tbb::enumerable_thread_specific<BlockMesher> meshers(mBlockVoxels);
    const auto& grid = field.grid();
    inBatches(origins.size(), progress, 0.0, 1.0, [&](size_t begin, size_t end) {
        tbb::parallel_for(tbb::blocked_range<size_t>(begin, end), [&](const auto& r) {
            BlockMesher& mesher = meshers.local();
            for (size_t i = r.begin(); i < r.end(); ++i) {
                meshes[i] = mesher.mesh(grid.tree(), grid.transform(), origins[i]);
            }
        });
    });
    std::vector<openvdb::Coord> changed;
    for (size_t i = 0; i < origins.size(); ++i) {
        const openvdb::Coord& origin = origins[i];
        if (meshes[i].empty()) {
            if (mBlocks.erase(origin)) changed.push_back(origin);
            continue;
        }
        meshes[i].version = mVersion;
        mBlocks[origin] = std::move(meshes[i]);
        changed.push_back(origin);
    }
    logChanges(std::move(changed));
}

void IncrementalMesher::logChanges(std::vector<openvdb::Coord> origins)
{
    if (origins.empty()) return;
    mLoggedOrigins += origins.size();
    auto& entry = mChangeLog[mVersion];
    entry.insert(entry.end(), origins.begin(), origins.end());
    if (mLoggedOrigins <= mCompactAbove || mChangeLog.size() < 2) return;
    // Merge the older half into its newest version: amortised O(1) per logged origin.
    auto middle = std::next(mChangeLog.begin(), std::ptrdiff_t(mChangeLog.size() / 2));
    std::set<openvdb::Coord> merged;
    for (auto it = mChangeLog.begin(); it != middle; ++it) merged.insert(it->second.begin(), it->second.end());
    const std::uint64_t newest = std::prev(middle)->first;
    mChangeLog.erase(mChangeLog.begin(), middle);
    mChangeLog[newest].assign(merged.begin(), merged.end());
    mLoggedOrigins = 0;
    for (const auto& [version, logged] : mChangeLog) mLoggedOrigins += logged.size();
    mCompactAbove = 2 * (mLoggedOrigins + mBlocks.size()) + 4096;
}

IncrementalMesher::Changes IncrementalMesher::changesSince(std::uint64_t version) const
{
    std::set<openvdb::Coord> origins;
    for (auto it = mChangeLog.upper_bound(version); it != mChangeLog.end(); ++it)
        origins.insert(it->second.begin(), it->second.end());
    Changes changes;
    for (const openvdb::Coord& origin : origins)
        (mBlocks.count(origin) ? changes.updated : changes.removed).push_back(origin);
    return changes;
}

std::size_t IncrementalMesher::triangleCount() const
{
    std::size_t count = 0;
    for (const auto& [origin, mesh] : mBlocks) count += mesh.triangles.size();
    return count;
}

std::size_t IncrementalMesher::memoryBytes() const
{
    std::size_t bytes = 0;
    for (const auto& [origin, mesh] : mBlocks) bytes += mesh.memoryBytes();
    return bytes;
}

TriangleMesh IncrementalMesher::weldedMesh() const { return weldBlocks(mBlocks, mBlockVoxels); }

TriangleMesh meshLevelSet(const FieldImage& field, int blockVoxels)
{
    IncrementalMesher mesher(blockVoxels);
    mesher.rebuild(field);
    return mesher.weldedMesh();
}

}  // namespace sculpt
