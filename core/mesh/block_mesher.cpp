// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/block_mesher.h"

#include "core/field/central_difference.h"
#include "core/field/dense_gather.h"
#include "core/mesh/marching_cubes_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sculpt {

namespace {

constexpr int kLeafDim = int(openvdb::FloatTree::LeafNodeType::DIM);

/// A voxel exactly on the iso-value would put the vertices of all its crossing edges on one
/// point: zero-area triangles that merge into non-manifold edges when a tool welds by position.
/// Keeping vertices this fraction of an edge away from voxels keeps them apart (the shift is far
/// below the interpolation error).
constexpr double kMinEdgeFraction = 1e-3;

/// Marks a slot holding an index among the foreign vertices (stored after the owned ones).
constexpr std::uint32_t kForeign = 1u << 31;

}  // namespace

/// Per-thread buffers, sized once for the block size and reused for every block.
struct BlockMesher::Scratch {
    int B;
    int S;                                    // B + 3 samples per axis, from origin - 1
    int N;                                    // B + 1 voxels per axis in [origin, origin + B]
    std::vector<float> values;                // S^3 samples
    std::vector<std::uint8_t> inside;         // N^3: sample < iso
    std::vector<std::uint32_t> slot;          // N^3 * 4: vertex of each edge (3 axes) and cell centre
    std::vector<std::uint8_t> cubes;          // B^3: sign configuration of each cell
    std::vector<std::uint8_t> rowHasSurface;  // B^2: some cell of row (x, y) may be cut
    std::vector<std::uint8_t> columnSigns;    // N^2: bit 0 some voxel inside, bit 1 some outside

    explicit Scratch(int blockVoxels)
        : B(blockVoxels), S(blockVoxels + 3), N(blockVoxels + 1), values(size_t(S) * S * S), inside(size_t(N) * N * N),
          slot(size_t(N) * N * N * 4), cubes(size_t(B) * B * B), rowHasSurface(size_t(B) * B),
          columnSigns(size_t(N) * N)
    {}

    void gather(const openvdb::FloatTree& tree, const openvdb::Coord& origin);
    /// Fills `inside`; false if the block's voxels all have one sign.
    bool classify();
    /// Fills `cubes` and `rowHasSurface` from `inside`.
    void configureCells();
};

void BlockMesher::Scratch::gather(const openvdb::FloatTree& tree, const openvdb::Coord& origin)
{
    gatherDense(tree, openvdb::CoordBBox(origin.offsetBy(-1), origin.offsetBy(B + 1)), values.data());
}

bool BlockMesher::Scratch::classify()
{
    int insideCount = 0;
    for (int x = 0; x < N; ++x) {
        for (int y = 0; y < N; ++y) {
            const float* row = &values[denseIndex(S, S, x + 1, y + 1, 1)];
            std::uint8_t* flags = &inside[denseIndex(N, N, x, y, 0)];
            int count = 0;
            for (int z = 0; z < N; ++z) {
                flags[z] = row[z] < 0.0f;
                count += flags[z];
            }
            columnSigns[size_t(x * N + y)] = std::uint8_t((count > 0 ? 1 : 0) | (count < N ? 2 : 0));
            insideCount += count;
        }
    }
    return insideCount > 0 && insideCount < N * N * N;
}

void BlockMesher::Scratch::configureCells()
{
    for (int x = 0; x < B; ++x) {
        for (int y = 0; y < B; ++y) {
            // A row of cells is cut only if its four voxel columns hold both signs.
            const int signs = columnSigns[size_t(x * N + y)] | columnSigns[size_t((x + 1) * N + y)] |
                              columnSigns[size_t(x * N + y + 1)] | columnSigns[size_t((x + 1) * N + y + 1)];
            rowHasSurface[size_t(x * B + y)] = signs == 3;
            if (signs != 3) continue;
            const std::uint8_t* c0 = &inside[size_t((x * N + y) * N)];
            const std::uint8_t* c1 = &inside[size_t(((x + 1) * N + y) * N)];
            const std::uint8_t* c2 = &inside[size_t((x * N + y + 1) * N)];
            const std::uint8_t* c3 = &inside[size_t(((x + 1) * N + y + 1) * N)];
            std::uint8_t* row = &cubes[size_t((x * B + y) * B)];
            for (int z = 0; z < B; ++z) {  // corner c has offset bits (x, y, z) = (c&1, c>>1&1, c>>2)
                const int low = c0[z] | c1[z] << 1 | c2[z] << 2 | c3[z] << 3;
                const int high = c0[z + 1] | c1[z + 1] << 1 | c2[z + 1] << 2 | c3[z + 1] << 3;
                row[z] = std::uint8_t(low | high << 4);
            }
        }
    }
}

void BlockMesher::validateBlockSize(int blockVoxels)
{
    if (blockVoxels < kLeafDim || blockVoxels > 64 || blockVoxels % kLeafDim != 0) {
        throw std::invalid_argument("block size must be a multiple of 8 between 8 and 64");
    }
}

BlockMesher::BlockMesher(int blockVoxels)
{
    validateBlockSize(blockVoxels);
    mScratch = std::make_unique<Scratch>(blockVoxels);
}

BlockMesher::~BlockMesher() = default;
BlockMesher::BlockMesher(BlockMesher&&) noexcept = default;

namespace {

/// Index-to-world maps of a linear transform, applied without virtual calls.
struct Placement {
    openvdb::Mat4d worldFromIndex;  // row-vector convention, as OpenVDB
    openvdb::Mat3d normalFromGradient;

    explicit Placement(const openvdb::math::Transform& xform)
        : worldFromIndex(xform.baseMap()->getAffineMap()->getMat4()),
          normalFromGradient(worldFromIndex.getMat3().inverse())
    {}

    openvdb::Vec3d point(const openvdb::Vec3d& p) const { return worldFromIndex.transform(p); }
    openvdb::Vec3d normal(const openvdb::Vec3d& g) const { return normalFromGradient * g; }
};

/// Builds one block's mesh from its samples in three passes: vertices on crossing edges in key
/// order (owned, then foreign: no sort needed), then cell triangles, then centre vertices.
class BlockBuilder {
public:
    BlockBuilder(BlockMesher::Scratch& scratch, const Placement& place, const openvdb::Coord& blockOrigin,
                 BlockMesh& mesh)
        : mScratch(scratch), mB(scratch.B), mN(scratch.N), mPlacement(place), mOrigin(blockOrigin), mOut(mesh)
    {}

    void run()
    {
        createVertices();
        createTriangles();
    }

private:
    BlockMesher::Scratch& mScratch;
    const int mB, mN;
    const Placement& mPlacement;
    const openvdb::Coord mOrigin;
    BlockMesh& mOut;
    BlockMesh mForeign;
    const mc::Case* const mCases = &mc::cubeCase(0);  // the 256 cases, contiguous

    size_t voxel(int x, int y, int z) const { return denseIndex(mN, mN, x, y, z); }
    float value(int x, int y, int z) const
    {
        return mScratch.values[denseIndex(mScratch.S, mScratch.S, x + 1, y + 1, z + 1)];
    }

    unsigned cubeIndex(int x, int y, int z) const { return mScratch.cubes[denseIndex(mB, mB, x, y, z)]; }
    bool rowHasSurface(int x, int y) const
    {
        return x >= 0 && y >= 0 && x < mB && y < mB && mScratch.rowHasSurface[size_t(x * mB + y)];
    }
    /// Edges from voxel row (x, y) belong only to cells of rows x-1..x, y-1..y.
    bool touchesSurface(int x, int y) const
    {
        return rowHasSurface(x, y) || rowHasSurface(x - 1, y) || rowHasSurface(x, y - 1) || rowHasSurface(x - 1, y - 1);
    }

    const mc::Triangulation& triangulation(int x, int y, int z, unsigned cube) const
    {
        const mc::Case& info = mCases[cube];
        unsigned bits = 0;
        for (int k = 0; k < info.ambiguousFaceCount; ++k) {
            const auto& fc = mc::face(info.ambiguousFaces[size_t(k)]).corners;
            auto corner = [&](int c) { return value(x + (c & 1), y + (c >> 1 & 1), z + (c >> 2 & 1)); };
            bits |= unsigned(mc::insideCornersJoin(corner(fc[0]), corner(fc[1]), corner(fc[2]), corner(fc[3]))) << k;
        }
        return info.triangulation(bits);
    }

    void createVertices()
    {
        for (int x = 0; x < mN; ++x) {
            for (int y = 0; y < mN; ++y) {
                if (!touchesSurface(x, y)) continue;
                for (int z = 0; z < mN; ++z) {
                    const bool owned = x < mB && y < mB && z < mB;
                    const std::uint8_t in = mScratch.inside[voxel(x, y, z)];
                    const size_t base = voxel(x, y, z) * 4;
                    if (x < mB && mScratch.inside[voxel(x + 1, y, z)] != in)
                        mScratch.slot[base + 0] = emit(x, y, z, 0, owned);
                    if (y < mB && mScratch.inside[voxel(x, y + 1, z)] != in)
                        mScratch.slot[base + 1] = emit(x, y, z, 1, owned);
                    if (z < mB && mScratch.inside[voxel(x, y, z + 1)] != in)
                        mScratch.slot[base + 2] = emit(x, y, z, 2, owned);
                    if (owned && rowHasSurface(x, y)) reserveCentre(x, y, z);
                }
            }
        }
        mOut.ownedCount = std::uint32_t(mOut.positions.size());
        mOut.positions.insert(mOut.positions.end(), mForeign.positions.begin(), mForeign.positions.end());
        mOut.normals.insert(mOut.normals.end(), mForeign.normals.begin(), mForeign.normals.end());
        mOut.keys.insert(mOut.keys.end(), mForeign.keys.begin(), mForeign.keys.end());
    }

    openvdb::Vec3d gradient(int x, int y, int z) const
    {
        return centralDifference([this](int i, int j, int k) { return value(i, j, k); }, x, y, z);
    }

    std::uint32_t emit(int x, int y, int z, int axis, bool owned)
    {
        const int ux = x + (axis == 0), uy = y + (axis == 1), uz = z + (axis == 2);
        const double f0 = value(x, y, z), f1 = value(ux, uy, uz);
        const double t = std::clamp(f0 / (f0 - f1), kMinEdgeFraction, 1.0 - kMinEdgeFraction);
        openvdb::Vec3d p(mOrigin.x() + x, mOrigin.y() + y, mOrigin.z() + z);
        p[axis] += t;
        const openvdb::Vec3d world = mPlacement.point(p);
        openvdb::Vec3d n = mPlacement.normal(gradient(x, y, z) * (1.0 - t) + gradient(ux, uy, uz) * t);
        if (!(n.lengthSqr() > 0.0)) n = openvdb::Vec3d(0.0), n[axis] = f1 > f0 ? 1.0 : -1.0;
        n.normalize();

        BlockMesh& target = owned ? mOut : mForeign;
        target.positions.push_back({float(world.x()), float(world.y()), float(world.z())});
        target.normals.push_back({float(n.x()), float(n.y()), float(n.z())});
        target.keys.push_back(edgeKey(mOrigin.x() + x, mOrigin.y() + y, mOrigin.z() + z, axis));
        const auto index = std::uint32_t(target.positions.size() - 1);
        return owned ? index : index | kForeign;
    }

    /// A cell whose loop is fanned around a centre gets its vertex now, in key order (the
    /// cell's key follows its three edges); position and normal are filled in later.
    void reserveCentre(int x, int y, int z)
    {
        const unsigned cube = cubeIndex(x, y, z);
        if (!mCases[cube].mayUseCentre || !triangulation(x, y, z, cube).centreLoopSize) return;
        mScratch.slot[voxel(x, y, z) * 4 + 3] = std::uint32_t(mOut.positions.size());
        mOut.positions.push_back({0.0f, 0.0f, 0.0f});
        mOut.normals.push_back({0.0f, 0.0f, 0.0f});
        mOut.keys.push_back(edgeKey(mOrigin.x() + x, mOrigin.y() + y, mOrigin.z() + z, 3));
    }

    std::uint32_t vertexOfEdge(int x, int y, int z, int edge) const
    {
        const int c = mc::edgeCorner(edge);
        const std::uint32_t slot =
            mScratch.slot[voxel(x + (c & 1), y + (c >> 1 & 1), z + (c >> 2 & 1)) * 4 + size_t(mc::edgeAxis(edge))];
        return slot & kForeign ? mOut.ownedCount + (slot & ~kForeign) : slot;
    }

    void createTriangles()
    {
        for (int x = 0; x < mB; ++x) {
            for (int y = 0; y < mB; ++y) {
                if (!rowHasSurface(x, y)) continue;
                for (int z = 0; z < mB; ++z) {
                    const unsigned cube = cubeIndex(x, y, z);
                    if (cube == 0 || cube == 255) continue;
                    cell(x, y, z, triangulation(x, y, z, cube));
                }
            }
        }
    }

    void cell(int x, int y, int z, const mc::Triangulation& t)
    {
        const std::uint32_t centre = t.centreLoopSize ? placeCentre(x, y, z, t) : 0;
        for (int i = 0; i < t.triangleCount; ++i) {
            std::array<std::uint32_t, 3> tri;
            for (int k = 0; k < 3; ++k) {
                const int e = t.edges[size_t(i)][size_t(k)];
                tri[size_t(k)] = e == mc::kCentre ? centre : vertexOfEdge(x, y, z, e);
            }
            mOut.triangles.push_back(tri);
        }
    }

    /// Mean position and normal of the loop's vertices.
    std::uint32_t placeCentre(int x, int y, int z, const mc::Triangulation& t)
    {
        openvdb::Vec3d p(0.0), n(0.0);
        for (int i = 0; i < t.centreLoopSize; ++i) {
            const std::uint32_t v = vertexOfEdge(x, y, z, t.centreLoop[size_t(i)]);
            p += openvdb::Vec3d(mOut.positions[v][0], mOut.positions[v][1], mOut.positions[v][2]);
            n += openvdb::Vec3d(mOut.normals[v][0], mOut.normals[v][1], mOut.normals[v][2]);
        }
        p /= double(t.centreLoopSize);
        n.normalize();
        const std::uint32_t index = mScratch.slot[voxel(x, y, z) * 4 + 3];
        mOut.positions[index] = {float(p.x()), float(p.y()), float(p.z())};
        mOut.normals[index] = {float(n.x()), float(n.y()), float(n.z())};
        return index;
    }
};

}  // namespace

BlockMesh BlockMesher::mesh(const openvdb::FloatTree& tree, const openvdb::math::Transform& xform,
                            const openvdb::Coord& origin)
{
    Scratch& s = *mScratch;
    BlockMesh out;
    s.gather(tree, origin);
    if (!s.classify()) return out;
    s.configureCells();
    const Placement placement(xform);
    BlockBuilder(s, placement, origin, out).run();
    // Cached for long: give back the growth slack of push_back (about a third of the bytes).
    out.positions.shrink_to_fit();
    out.normals.shrink_to_fit();
    out.keys.shrink_to_fit();
    out.triangles.shrink_to_fit();
    return out;
}

}  // namespace sculpt
