// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file block_mesher.h
/// @brief Marching cubes over one block of a narrow-band level set.
///
/// A block is the set of cells whose minimum corner lies in [origin, origin + B)^3, B a multiple
/// of the 8-voxel leaf. The block reads voxels [origin - 1, origin + B + 1]^3: one voxel of apron
/// for the cells on its far faces and one more on each side for central-difference gradients.
/// Vertices sit on cell edges at t = (iso - f0) / (f1 - f0), f0 at the edge's lower end; normals
/// are the normalised linear interpolation of the two end gradients. Both are computed from the
/// same inputs in the same order by every block that meets an edge, so they agree bit for bit.

#include "core/mesh/block_mesh.h"

#include <openvdb/openvdb.h>

#include <memory>

namespace sculpt {

class BlockMesher {
public:
    /// @param blockVoxels B, a multiple of 8 between 8 and 64.
    /// @throws std::invalid_argument otherwise.
    explicit BlockMesher(int blockVoxels);
    /// @throws std::invalid_argument unless blockVoxels is a multiple of 8 in [8, 64].
    static void validateBlockSize(int blockVoxels);
    ~BlockMesher();
    BlockMesher(BlockMesher&&) noexcept;

    /// Meshes the block at `origin` (a multiple of B) of the zero iso-surface of `tree`.
    /// Cost: O(B^3) for the gather and sign test, plus O(triangles). Reusable; one per thread.
    BlockMesh mesh(const openvdb::FloatTree& tree, const openvdb::math::Transform& xform, const openvdb::Coord& origin);

    struct Scratch;  ///< per-thread buffers (defined in the .cpp)

private:
    std::unique_ptr<Scratch> mScratch;
};

}  // namespace sculpt
