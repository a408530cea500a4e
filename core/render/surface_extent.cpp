// SPDX-License-Identifier: Apache-2.0
#include "core/render/surface_extent.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

void SurfaceExtent::add(const FieldImage& field)
{
    using LeafT = openvdb::FloatTree::LeafNodeType;
    const auto& xform = field.grid().transform();
    const openvdb::CoordBBox box = field.grid().evalActiveVoxelBoundingBox();
    if (!box.empty()) bounds.expand(xform.indexToWorld(box));
    const double half = 0.5 * (LeafT::DIM - 1);
    for (auto leaf = field.grid().tree().cbeginLeaf(); leaf; ++leaf) {
        leafCentres.push_back(xform.indexToWorld(leaf->origin().asVec3d() + openvdb::Vec3d(half)));
    }
    padWorld = std::max(padWorld, std::sqrt(3.0) * half * field.voxelSize());
}

}  // namespace sculpt
