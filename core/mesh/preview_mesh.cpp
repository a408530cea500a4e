// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/preview_mesh.h"

#include "core/mesh/block_mesh.h"
#include "core/mesh/incremental_mesher.h"

#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>

namespace sculpt {

int previewStride(const FieldImage& field, std::size_t triangleBudget)
{
    const double estimate = double(field.grid().activeVoxelCount()) / std::max(1.0, field.halfWidthVoxels());
    int stride = 1;
    while (stride < 8 && estimate / double(stride * stride) > double(triangleBudget)) stride *= 2;
    return stride;
}

TriangleMesh previewMesh(const FieldImage& field, int stride)
{
    if (stride != 1 && stride != 2 && stride != 4 && stride != 8)
        throw std::invalid_argument("previewMesh: the stride must be 1, 2, 4 or 8");
    if (stride == 1) return meshLevelSet(field);
    const openvdb::FloatGrid& fine = field.grid();
    auto xform = fine.transform().copy();
    xform->preScale(double(stride));  // index i of the coarse grid is index stride i of the fine one
    // The background must span a coarse voxel (FieldImage's rule); the samples keep the fine band's.
    auto coarse = makeLevelSetGrid(*xform, std::max(fine.background(), float(1.01 * stride * field.voxelSize())));
    // Every voxel of a coarse leaf takes the fine value at its sample, inactive ones too: their
    // signs hold inside and outside where the thin band left no sample active.
    std::vector<openvdb::FloatTree::LeafNodeType*> leaves;
    for (auto leaf = fine.tree().cbeginLeaf(); leaf; ++leaf) {
        const openvdb::Coord o = leaf->origin();
        const openvdb::Coord c(floorToMultiple(o.x() / stride, 8), floorToMultiple(o.y() / stride, 8),
                               floorToMultiple(o.z() / stride, 8));
        if (!coarse->tree().probeLeaf(c)) leaves.push_back(coarse->tree().touchLeaf(c));
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
        auto in = fine.getConstAccessor();
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            for (auto v = leaves[i]->beginValueAll(); v; ++v) {
                const openvdb::Coord c = v.getCoord(), ijk(c.x() * stride, c.y() * stride, c.z() * stride);
                v.setValue(in.getValue(ijk));
                v.setValueOn(in.isValueOn(ijk));
            }
        }
    });
    openvdb::tools::signedFloodFill(coarse->tree(), true, 1, /*minLevel: tiles only*/ 1);
    return meshLevelSet(FieldImage(coarse, field.units()));
}

}  // namespace sculpt
