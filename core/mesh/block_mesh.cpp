// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/block_mesh.h"

namespace sculpt {

std::size_t BlockMesh::memoryBytes() const
{
    return positions.capacity() * sizeof(positions[0]) + normals.capacity() * sizeof(normals[0]) +
           keys.capacity() * sizeof(keys[0]) + triangles.capacity() * sizeof(triangles[0]);
}

}  // namespace sculpt
