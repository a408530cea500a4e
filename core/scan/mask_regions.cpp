// SPDX-License-Identifier: Apache-2.0
#include "core/scan/mask_regions.h"

#include <array>
#include <cstdint>
#include <vector>

namespace sculpt {

namespace {

using Leaf = openvdb::BoolTree::LeafNodeType;
// A leaf's voxels as 8 words, one per x; bit y * 8 + z (OpenVDB's offset order).
using Bits = std::array<std::uint64_t, 8>;

constexpr std::uint64_t kZ0 = 0x0101010101010101ull;  // bits with z = 0
constexpr std::uint64_t kZ7 = kZ0 << 7;               // bits with z = 7
constexpr std::uint64_t kY0 = 0xFFull;                // bits with y = 0
constexpr std::uint64_t kY7 = kY0 << 56;              // bits with y = 7

Bits bitsOf(const Leaf::NodeMaskType& mask)
{
    Bits b;
    for (int x = 0; x < 8; ++x) b[size_t(x)] = mask.getWord<std::uint64_t>(openvdb::Index(x));
    return b;
}

bool empty(const Bits& b)
{
    std::uint64_t any = 0;
    for (const auto w : b) any |= w;
    return any == 0;
}

/// `b` and its face neighbours inside the leaf.
Bits dilated(const Bits& b)
{
    Bits d;
    for (size_t x = 0; x < 8; ++x) {
        const std::uint64_t w = b[x];
        d[x] = w | ((w << 1) & ~kZ0) | ((w >> 1) & ~kZ7) | (w << 8) | (w >> 8) | (x > 0 ? b[x - 1] : 0) |
               (x < 7 ? b[x + 1] : 0);
    }
    return d;
}

/// Bits of `b` on one face of the leaf, moved to the opposite face of the neighbour there.
Bits acrossFace(const Bits& b, int axis, int side)
{
    Bits n{};
    for (size_t x = 0; x < 8; ++x) {
        if (axis == 0) {
            n[side < 0 ? 7 : 0] = b[side < 0 ? 0 : 7];
            break;
        }
        if (axis == 1) n[x] = side < 0 ? (b[x] & kY0) << 56 : (b[x] & kY7) >> 56;
        if (axis == 2) n[x] = side < 0 ? (b[x] & kZ0) << 7 : (b[x] & kZ7) >> 7;
    }
    return n;
}

struct Front {
    openvdb::Coord origin;
    Bits seeds;
};

/// Adds to `region` the voxels of `mask` face-connected to `seed` that are not in `visited`, and
/// marks them visited.
void flood(const openvdb::BoolTree& mask, openvdb::BoolTree& visited, const openvdb::Coord& seed, MaskRegion& region)
{
    const openvdb::tree::ValueAccessor<const openvdb::BoolTree> in(mask);
    openvdb::tree::ValueAccessor<openvdb::BoolTree> done(visited);
    std::vector<Front> queue;
    const int low = ~int(Leaf::DIM - 1);
    Front start{openvdb::Coord(seed.x() & low, seed.y() & low, seed.z() & low), Bits{}};
    const openvdb::Index offset = Leaf::coordToOffset(seed);
    start.seeds[offset >> 6] = std::uint64_t(1) << (offset & 63);
    queue.push_back(start);
    while (!queue.empty()) {
        const Front front = queue.back();
        queue.pop_back();
        Bits allowed;
        if (const Leaf* leaf = in.probeConstLeaf(front.origin)) {
            allowed = bitsOf(leaf->getValueMask());
        } else {
            allowed.fill(in.isValueOn(front.origin) ? ~std::uint64_t(0) : 0);  // an active tile, or nothing
        }
        Leaf* marked = done.probeLeaf(front.origin);
        if (marked) {
            const Bits filled = bitsOf(marked->getValueMask());
            for (size_t x = 0; x < 8; ++x) allowed[x] &= ~filled[x];
        }
        Bits grown;
        for (size_t x = 0; x < 8; ++x) grown[x] = front.seeds[x] & allowed[x];
        if (empty(grown)) continue;
        for (Bits next = grown;; grown = next) {
            next = dilated(grown);
            for (size_t x = 0; x < 8; ++x) next[x] &= allowed[x];
            if (next == grown) break;
        }
        if (!marked) marked = done.touchLeaf(front.origin);
        MaskRegion::Bits voxels;
        for (size_t x = 0; x < 8; ++x) {
            marked->getValueMask().getWord<std::uint64_t>(openvdb::Index(x)) |= grown[x];
            voxels.getWord<std::uint64_t>(openvdb::Index(x)) = grown[x];
        }
        region.leaves.emplace_back(front.origin, voxels);
        for (int axis = 0; axis < 3; ++axis) {
            for (const int side : {-1, 1}) {
                Front neighbour{front.origin, acrossFace(grown, axis, side)};
                neighbour.origin[axis] += side * int(Leaf::DIM);
                if (!empty(neighbour.seeds)) queue.push_back(neighbour);
            }
        }
    }
}

}  // namespace

openvdb::Index64 MaskRegion::voxelCount() const
{
    openvdb::Index64 count = 0;
    for (const auto& leaf : leaves) count += leaf.second.countOn();
    return count;
}

openvdb::BoolTree::Ptr MaskRegion::tree() const
{
    auto result = std::make_shared<openvdb::BoolTree>(false);
    openvdb::tree::ValueAccessor<openvdb::BoolTree> out(*result);
    for (const auto& [origin, voxels] : leaves) out.touchLeaf(origin)->getValueMask() |= voxels;
    return result;
}

MaskRegion connectedRegion(const openvdb::BoolTree& mask, const openvdb::Coord& seed)
{
    openvdb::BoolTree visited(false);
    MaskRegion region;
    flood(mask, visited, seed, region);
    return region;
}

void forEachConnectedRegion(const openvdb::BoolTree& mask, const std::function<void(const MaskRegion& region)>& visit)
{
    openvdb::BoolTree visited(false);
    const openvdb::tree::ValueAccessor<const openvdb::BoolTree> seen(visited);
    MaskRegion region;
    for (auto it = mask.cbeginValueOn(); it; ++it) {
        if (seen.isValueOn(it.getCoord())) continue;
        region.leaves.clear();
        flood(mask, visited, it.getCoord(), region);
        visit(region);
    }
}

}  // namespace sculpt
