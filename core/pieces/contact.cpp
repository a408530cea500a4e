// SPDX-License-Identifier: Apache-2.0
#include "core/pieces/contact.h"

#include "core/field/placed_box.h"
#include "core/mesh/block_mesh.h"

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sculpt {

namespace {

using openvdb::Coord;
using openvdb::Mat4d;
using openvdb::Vec3d;

/// Maps `moving`'s field world into `other`'s index space.
class ToOther {
public:
    ToOther(const ContactBody& moving, const ContactBody& other)
        : mToOtherWorld(moving.placement * other.placement.inverse()), mOther(other.field.grid().transform())
    {}
    Vec3d operator()(const Vec3d& world) const { return mOther.worldToIndex(mToOtherWorld.transform(world)); }

private:
    Mat4d mToOtherWorld;
    const openvdb::math::Transform& mOther;
};

/// Where `other`'s blocks are: each block's origin, and the box of all of them (block origins).
struct BlockSet {
    const IncrementalMesher& mesher;
    openvdb::CoordBBox origins;  ///< empty when the piece has no surface

    explicit BlockSet(const IncrementalMesher& m) : mesher(m)
    {
        for (const auto& [origin, mesh] : m.blocks())
            if (!mesh.empty()) origins.expand(origin);
    }
    /// Whether a block of the range of origins [lo, hi] holds surface.
    bool anyIn(const Coord& lo, const Coord& hi) const
    {
        const int b = mesher.blockVoxels();
        for (int x = lo.x(); x <= hi.x(); x += b)
            for (int y = lo.y(); y <= hi.y(); y += b)
                for (int z = lo.z(); z <= hi.z(); z += b) {
                    const auto it = mesher.blocks().find(Coord(x, y, z));
                    if (it != mesher.blocks().end() && !it->second.empty()) return true;
                }
        return false;
    }
};

/// The origins of `other`'s blocks whose cells a trilinear sample anywhere in `moving`'s block
/// at `origin` reads: the block's corners taken into other's index space, floored to blocks.
std::pair<Coord, Coord> blocksUnder(const Coord& origin, int movingBlock, const openvdb::math::Transform& moving,
                                    const ToOther& toOther, int otherBlock)
{
    Vec3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d index(origin.x() + (corner & 1 ? movingBlock : 0), origin.y() + (corner & 2 ? movingBlock : 0),
                          origin.z() + (corner & 4 ? movingBlock : 0));
        const Vec3d p = toOther(moving.indexToWorld(index));
        lo = openvdb::math::minComponent(lo, p);
        hi = openvdb::math::maxComponent(hi, p);
    }
    const auto block = [otherBlock](const Vec3d& v) {
        return Coord(floorToMultiple(int(std::floor(v.x())), otherBlock),
                     floorToMultiple(int(std::floor(v.y())), otherBlock),
                     floorToMultiple(int(std::floor(v.z())), otherBlock));
    };
    return {block(lo), block(hi)};
}

/// Samples `other`'s phi at the vertices [0, count) of one block of `moving`.
void sampleVertices(const BlockMesh& mesh, std::size_t count, const ToOther& toOther,
                    const openvdb::FloatGrid::ConstAccessor& accessor, Penetration& out)
{
    for (std::size_t v = 0; v < count; ++v) {
        const auto& p = mesh.positions[v];
        const double phi = openvdb::tools::BoxSampler::sample(accessor, toOther(Vec3d(p[0], p[1], p[2])));
        ++out.sampledVertices;
        if (phi < 0.0) {
            ++out.penetratingVertices;
            out.deepest = std::max(out.deepest, -phi);
        }
    }
}

/// One block of `moving` against `other`.
void blockAgainst(const Coord& origin, const BlockMesh& mesh, const ContactBody& moving, const BlockSet& other,
                  const ToOther& toOther, const openvdb::FloatGrid::ConstAccessor& accessor, Penetration& out)
{
    const int otherBlock = other.mesher.blockVoxels();
    const auto [lo, hi] =
        blocksUnder(origin, moving.mesher.blockVoxels(), moving.field.grid().transform(), toOther, otherBlock);
    if (!other.origins.hasOverlap(openvdb::CoordBBox(lo, hi))) return;  // outside the other's surface
    if (other.anyIn(lo, hi)) return sampleVertices(mesh, mesh.ownedCount, toOther, accessor, out);
    Penetration probe;
    sampleVertices(mesh, 1, toOther, accessor, probe);
    out.sampledVertices += 1;
    if (!probe.any()) return;
    out.penetratingVertices += mesh.ownedCount;
    out.deepest = std::max(out.deepest, probe.deepest);
}

/// A body's box in its field's world: the one it carries, else its leaves'.
openvdb::BBoxd boxOf(const ContactBody& body) { return body.box.empty() ? leafWorldBox(body.field) : body.box; }

/// Whether the global boxes of the two meet where they are placed.
bool boxesMeet(const ContactBody& moving, const ContactBody& other)
{
    const openvdb::BBoxd own = boxOf(moving), theirs = boxOf(other);
    if (own.empty() || theirs.empty()) return false;
    return placedBox(own, moving.placement * other.placement.inverse()).hasOverlap(theirs);
}

Penetration combined(Penetration a, const Penetration& b)
{
    a.sampledVertices += b.sampledVertices;
    a.penetratingVertices += b.penetratingVertices;
    a.deepest = std::max(a.deepest, b.deepest);
    return a;
}

}  // namespace

Penetration penetration(const ContactBody& moving, const ContactBody& other)
{
    if (!boxesMeet(moving, other)) return {};  // apart: no block of either is looked at
    const BlockSet otherBlocks(other.mesher);
    if (otherBlocks.origins.empty()) return {};
    const ToOther toOther(moving, other);
    std::vector<std::pair<Coord, const BlockMesh*>> blocks;
    for (const auto& [origin, mesh] : moving.mesher.blocks())
        if (mesh.ownedCount > 0) blocks.emplace_back(origin, &mesh);
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, blocks.size(), 16), Penetration{},
        [&](const tbb::blocked_range<std::size_t>& range, Penetration found) {
            const openvdb::FloatGrid::ConstAccessor accessor = other.field.grid().getConstAccessor();
            for (std::size_t i = range.begin(); i != range.end(); ++i)
                blockAgainst(blocks[i].first, *blocks[i].second, moving, otherBlocks, toOther, accessor, found);
            return found;
        },
        &combined);
}

Penetration overlap(const ContactBody& a, const ContactBody& b)
{
    return combined(penetration(a, b), penetration(b, a));
}

double freeFraction(const ContactBody& moving, const ContactBody& other, const std::function<Mat4d(double)>& along,
                    int bisections)
{
    const auto overlapsAt = [&](double t) {
        return overlap(ContactBody{moving.field, moving.mesher, along(t), moving.box}, other).any();
    };
    if (!overlapsAt(1.0)) return 1.0;
    if (overlapsAt(0.0)) return 0.0;
    double free = 0.0, blocked = 1.0;
    for (int i = 0; i < bisections; ++i) {
        const double middle = 0.5 * (free + blocked);
        (overlapsAt(middle) ? blocked : free) = middle;
    }
    return free;
}

}  // namespace sculpt
