// SPDX-License-Identifier: Apache-2.0
#include "core/field/grid_tiles.h"

#include <cstring>

namespace sculpt {
namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }

template <typename Node>
void visitNodeTiles(const Node& node, float background, const TileVisit& visit)
{
    const auto* table = node.getTable();
    const auto& children = node.getChildMask();
    for (openvdb::Index i = 0; i < Node::NUM_VALUES; ++i) {
        if (children.isOn(i)) {
            if constexpr (Node::LEVEL > 1) visitNodeTiles(*table[i].getChild(), background, visit);
        } else if (!sameBits(table[i].getValue(), background)) {
            visit(openvdb::CoordBBox::createCube(node.offsetToGlobalCoord(i), Node::ChildNodeType::DIM),
                  table[i].getValue(), node.isValueMaskOn(i));
        }
    }
}

}  // namespace

void forEachTileOffBackground(const openvdb::FloatTree& tree, const TileVisit& visit)
{
    const auto& root = tree.root();
    const float background = tree.background();
    for (auto tile = root.cbeginValueAll(); tile; ++tile) {
        if (sameBits(*tile, background)) continue;
        visit(openvdb::CoordBBox::createCube(tile.getCoord(), openvdb::FloatTree::RootNodeType::ChildNodeType::DIM),
              *tile, tile.isValueOn());
    }
    for (auto child = root.cbeginChildOn(); child; ++child) visitNodeTiles(*child, background, visit);
}

}  // namespace sculpt
