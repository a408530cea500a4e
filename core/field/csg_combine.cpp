// SPDX-License-Identifier: Apache-2.0
#include "core/field/csg_combine.h"

#include "core/base/enum_names.h"
#include "core/field/band_rule.h"

#include <openvdb/tools/Composite.h>

#include <algorithm>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;

constexpr EnumNames<CsgOperation, 4> kOperationNames{{{CsgOperation::Union, "union"},
                                                      {CsgOperation::Difference, "difference"},
                                                      {CsgOperation::Intersection, "intersection"},
                                                      {CsgOperation::Replace, "replace"}}};

/// Voxel rule of the local operations, on values clamped to the sculpt's band.
float apply(CsgOperation op, float sculpt, float shape)
{
    return op == CsgOperation::Union ? std::min(sculpt, shape) : std::max(sculpt, -shape);
}

/// Union or difference over the leaf-sized cells of the shape's bounding box.
DirtyRegion combineLocally(openvdb::FloatGrid& grid, const openvdb::FloatGrid& shape, CsgOperation op)
{
    DirtyRegion touched;
    const float background = grid.background();
    const float outside = shape.background();  // where the shape is absent, neither op changes anything
    openvdb::CoordBBox box;
    shape.tree().evalLeafBoundingBox(box);
    auto acc = grid.getAccessor();
    auto shapeAcc = shape.getConstAccessor();
    for (const openvdb::Coord& origin : DirtyRegion::leafOriginsIn(box)) {
        const LeafT* from = shapeAcc.probeConstLeaf(origin);
        if (!from && shapeAcc.getValue(origin) >= outside) continue;
        LeafT* to = acc.touchLeaf(origin);
        for (auto it = to->beginValueAll(); it; ++it) {
            const BandValue band = toBand(apply(op, *it, shapeAcc.getValue(it.getCoord())), background);
            it.setValue(band.value);
            it.setValueOn(band.active);
        }
        touched.addVoxel(origin);
    }
    return touched;
}

}  // namespace

void combineWhole(openvdb::FloatGrid& a, openvdb::FloatGrid& b, CsgOperation operation)
{
    switch (operation) {
    case CsgOperation::Union: openvdb::tools::csgUnion(a, b); break;
    case CsgOperation::Difference: openvdb::tools::csgDifference(a, b); break;
    case CsgOperation::Intersection: openvdb::tools::csgIntersection(a, b); break;
    case CsgOperation::Replace: a.setTree(b.tree().copy()); break;
    }
}

CsgOperation csgFromName(const std::string& name) { return enumFromName(kOperationNames, name, "operation"); }

const char* csgName(CsgOperation operation) { return enumName(kOperationNames, operation); }

DirtyRegion combine(FieldImage& sculpt, const FieldImage& shape, CsgOperation operation)
{
    if (sculpt.grid().transform() != shape.grid().transform()) {
        throw InputError("the shape's voxels differ from the sculpt's (voxel size or placement)");
    }
    openvdb::FloatGrid& grid = sculpt.mutableGrid();
    DirtyRegion touched;
    switch (operation) {
    case CsgOperation::Union:
    case CsgOperation::Difference: touched = combineLocally(grid, shape.grid(), operation); break;
    case CsgOperation::Intersection: {
        touched = sculpt.allLeaves();
        auto copy = shape.grid().deepCopy();
        combineWhole(grid, *copy, CsgOperation::Intersection);
        break;
    }
    case CsgOperation::Replace:
        touched = sculpt.allLeaves();
        grid.setTree(shape.grid().tree().copy());
        break;
    }
    if (operation == CsgOperation::Intersection || operation == CsgOperation::Replace)
        touched.merge(sculpt.allLeaves());
    sculpt.markDirty(touched);
    return touched;
}

}  // namespace sculpt
