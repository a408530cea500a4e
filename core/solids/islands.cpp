// SPDX-License-Identifier: Apache-2.0
#include "core/solids/islands.h"

#include "core/field/csg_combine.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/LevelSetUtil.h>

#include <algorithm>
#include <limits>

namespace sculpt {

namespace {

openvdb::BBoxd worldBoundsOf(const openvdb::FloatGrid& grid)
{
    const openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    return grid.transform().indexToWorld(box);
}

/// `field` made of the islands of `islands` that `kept` picks (united: islands apart by more than
/// the band keep their voxels bit for bit, and nothing of the others is left, not even a band).
template <typename Kept>
void keepIslands(FieldImage& field, const std::vector<Island>& islands, const Kept& kept)
{
    openvdb::FloatGrid::Ptr grid = makeLevelSetGrid(field.grid().transform(), field.grid().background());
    grid->setName(field.grid().getName());
    for (std::size_t i = 0; i < islands.size(); ++i) {
        if (!kept(i)) continue;
        openvdb::FloatGrid::Ptr island = islands[i].grid->deepCopy();
        combineWhole(*grid, *island, CsgOperation::Union);
    }
    field.swapGrid(grid);
}

}  // namespace

std::vector<Island> findIslands(const FieldImage& field)
{
    std::vector<openvdb::FloatGrid::Ptr> grids;
    openvdb::tools::segmentSDF(field.grid(), grids);
    std::vector<Island> islands;
    for (auto& grid : grids) {
        const double volume = openvdb::tools::levelSetVolume(*grid);
        islands.push_back({grid, volume, worldBoundsOf(*grid)});
    }
    std::stable_sort(islands.begin(), islands.end(),
                     [](const Island& a, const Island& b) { return a.volume > b.volume; });
    return islands;
}

std::size_t removeIslandsUnder(FieldImage& field, double minVolume)
{
    const std::vector<Island> islands = findIslands(field);
    const auto large = [&](std::size_t i) { return islands[i].volume >= minVolume; };
    const std::size_t count = std::size_t(
        std::count_if(islands.begin(), islands.end(), [&](const Island& island) { return island.volume < minVolume; }));
    if (count > 0) keepIslands(field, islands, large);
    return count;
}

int islandAt(const std::vector<Island>& islands, const openvdb::Vec3d& world, double reachWorld)
{
    int best = -1;
    double nearest = reachWorld;
    for (std::size_t i = 0; i < islands.size(); ++i) {
        const openvdb::FloatGrid& grid = *islands[i].grid;
        const double d = openvdb::tools::BoxSampler::sample(grid.tree(), grid.transform().worldToIndex(world));
        if (d <= nearest) nearest = d, best = int(i);
    }
    return best;
}

void keepOrRemoveIsland(FieldImage& field, const std::vector<Island>& islands, std::size_t index, bool keep)
{
    keepIslands(field, islands, [&](std::size_t i) { return (i == index) == keep; });
}

}  // namespace sculpt
