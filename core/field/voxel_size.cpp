// SPDX-License-Identifier: Apache-2.0
#include "core/field/voxel_size.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"

#include <cmath>

namespace sculpt {

openvdb::math::Transform::Ptr voxelTransform(double voxelSize)
{
    if (!(voxelSize >= kMinVoxelSize) || !std::isfinite(voxelSize)) {
        throw InputError("a voxel size of " + formatNumber(voxelSize) + " is below the smallest a model may have (" +
                             formatNumber(kMinVoxelSize) + ")",
                         Remedy::CoarserVoxelSize);
    }
    return openvdb::math::Transform::createLinearTransform(voxelSize);
}

}  // namespace sculpt
