// SPDX-License-Identifier: Apache-2.0
#include "tests/support/grid_builders.h"

#include "core/primitives/analytic_shapes.h"

namespace sculpt::test {

FieldImage fieldFromVoxels(const std::map<openvdb::Coord, float>& values)
{
    auto grid = openvdb::FloatGrid::create(3.0f);
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    openvdb::CoordBBox box;
    for (const auto& [ijk, value] : values) box.expand(ijk);
    box.expand(1);
    auto acc = grid->getAccessor();
    for (auto it = box.begin(); it != box.end(); ++it) {
        const auto found = values.find(*it);
        acc.setValueOn(*it, found == values.end() ? 1.0f : found->second);
    }
    return FieldImage(grid);
}

FieldImage translated(const FieldImage& field, const openvdb::Vec3d& by)
{
    openvdb::FloatGrid::Ptr grid = field.grid().deepCopy();
    openvdb::math::Transform::Ptr xform = grid->transform().copy();
    xform->postTranslate(by);
    grid->setTransform(xform);
    return FieldImage(grid);
}

std::vector<Piece> bodyAndBallApart()
{
    std::vector<Piece> pieces{{{"body"}, makeSphere(10.0, 0.5)}, {{"ball", {0.9f, 0.3f, 0.2f}}, makeSphere(6.0, 0.5)}};
    pieces[1].placement.setTranslation(openvdb::Vec3d(30.0, 0.0, 0.0));
    return pieces;
}

}  // namespace sculpt::test
