// SPDX-License-Identifier: Apache-2.0
#include "core/field/band_repair.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"

#include <openvdb/tools/Count.h>
#include <openvdb/tools/LevelSetRebuild.h>

#include <algorithm>
#include <cmath>

namespace sculpt {

std::string whyNotNarrowBand(const openvdb::FloatGrid& grid)
{
    const auto values = openvdb::tools::minMax(grid.tree());
    if (!std::isfinite(values.min()) || !std::isfinite(values.max())) {
        throw InputError("grid '" + grid.getName() + "' holds values that are not finite numbers");
    }
    const float background = grid.background();
    if (grid.getGridClass() != openvdb::GRID_LEVEL_SET) return "its class is not 'level set'";
    if (!(double(background) >= grid.voxelSize()[0])) {
        return "its background " + formatNumber(background) + " is under a voxel";
    }
    // A tolerance for writers that store the band edge in half precision.
    const float reach = std::max(-values.min(), values.max());
    if (reach > background * 1.001f) {
        return "values reach " + formatNumber(reach) + ", beyond its background " + formatNumber(background);
    }
    return {};
}

openvdb::FloatGrid::Ptr rebuildNarrowBand(const openvdb::FloatGrid& grid, double halfWidthVoxels)
{
    auto band = openvdb::tools::levelSetRebuild(grid, 0.0f, float(halfWidthVoxels));
    band->setName(grid.getName());
    band->setGridClass(openvdb::GRID_LEVEL_SET);
    return band;
}

}  // namespace sculpt
