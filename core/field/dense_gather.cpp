// SPDX-License-Identifier: Apache-2.0
#include "core/field/dense_gather.h"

#include <algorithm>

namespace sculpt {

void gatherDense(const openvdb::FloatTree& tree, const openvdb::CoordBBox& box, float* dst)
{
    using LeafT = openvdb::FloatTree::LeafNodeType;
    constexpr int kLeafDim = int(LeafT::DIM);
    const openvdb::Coord lo = box.min(), hi = box.max(), dim = box.dim();
    openvdb::tree::ValueAccessor<const openvdb::FloatTree> acc(tree);
    for (int lx = lo.x() & ~(kLeafDim - 1); lx <= hi.x(); lx += kLeafDim) {
        for (int ly = lo.y() & ~(kLeafDim - 1); ly <= hi.y(); ly += kLeafDim) {
            for (int lz = lo.z() & ~(kLeafDim - 1); lz <= hi.z(); lz += kLeafDim) {
                const openvdb::Coord leafOrigin(lx, ly, lz);
                const LeafT* leaf = acc.probeConstLeaf(leafOrigin);
                const float tile = leaf ? 0.0f : acc.getValue(leafOrigin);
                const int x0 = std::max(lx, lo.x()), x1 = std::min(lx + kLeafDim - 1, hi.x());
                const int y0 = std::max(ly, lo.y()), y1 = std::min(ly + kLeafDim - 1, hi.y());
                const int z0 = std::max(lz, lo.z()), z1 = std::min(lz + kLeafDim - 1, hi.z());
                for (int x = x0; x <= x1; ++x) {
                    for (int y = y0; y <= y1; ++y) {
                        float* out =
                            dst + (size_t(x - lo.x()) * dim.y() + size_t(y - lo.y())) * dim.z() + size_t(z0 - lo.z());
                        if (!leaf) {
                            std::fill(out, out + (z1 - z0 + 1), tile);
                            continue;
                        }
                        const float* src = leaf->buffer().data() + LeafT::coordToOffset(openvdb::Coord(x, y, z0));
                        std::copy(src, src + (z1 - z0 + 1), out);
                    }
                }
            }
        }
    }
}

}  // namespace sculpt
