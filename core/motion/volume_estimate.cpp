// SPDX-License-Identifier: Apache-2.0
#include "core/motion/volume_estimate.h"

#include "core/field/central_difference.h"
#include "core/field/grid_tiles.h"

#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_reduce.h>

#include <cmath>

namespace sculpt {

VolumeArea estimateVolumeArea(const openvdb::FloatGrid& grid)
{
    using Range = openvdb::tree::LeafManager<const openvdb::FloatTree>::LeafRange;
    const double h = grid.voxelSize()[0];
    openvdb::tree::LeafManager<const openvdb::FloatTree> leaves(grid.tree());
    const auto voxels = tbb::parallel_reduce(
        leaves.leafRange(), std::pair<double, double>(0.0, 0.0),
        [&](const Range& r, std::pair<double, double> sum) {
            auto acc = grid.getConstAccessor();
            for (auto leaf = r.begin(); leaf; ++leaf) {
                for (auto it = leaf->cbeginValueAll(); it; ++it) {
                    const float phi = *it;
                    if (phi <= -2.0f * float(h)) {
                        sum.first += 1.0;
                        continue;
                    }
                    if (phi >= 2.0f * float(h)) continue;
                    const openvdb::Coord& c = it.getCoord();
                    double g = 0.5 * centralDifferenceAt(acc, c).length() / h;
                    if (!(g > 0.1)) g = 1.0;
                    const double d = phi / (g * h);  // distance in voxels
                    sum.first += std::clamp(0.5 - d, 0.0, 1.0);
                    sum.second += std::max(0.0, 1.0 - std::abs(d));
                }
            }
            return sum;
        },
        [](auto a, auto b) { return std::pair<double, double>(a.first + b.first, a.second + b.second); });
    double tileVoxels = 0.0;
    forEachTileOffBackground(grid.tree(), [&](const openvdb::CoordBBox& block, float value, bool) {
        if (value < 0.0f) tileVoxels += double(block.volume());
    });
    return {(voxels.first + tileVoxels) * h * h * h, voxels.second * h * h};
}

}  // namespace sculpt
