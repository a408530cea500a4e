// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file usd_mesh_file.h
/// @brief A mesh sequence as a USD text layer (`.usda`): one Mesh prim with fixed face lists and
///        its points, velocities and extent as time samples, which Blender's USD import and
///        Mesh Sequence Cache modifier play (Debian has no Alembic or USD library to write with).
///
/// Time codes are the sequence's frame numbers (firstFrame onwards) at framesPerSecond; lengths
/// are millimetres (metersPerUnit 0.001), Z up. Velocities, in millimetres per second, are the
/// central differences of the frames (one-sided at the ends). Stable vertex ids, when given, go
/// into the vertex primvar `sculptVertexId`.

#include "core/io/mesh_sequence.h"

namespace sculpt {

/// Writes `mesh` as `.usda`, atomically. @throws InputError naming the file if its directory is
/// missing, the sequence is malformed (checkMeshSequence) or the write fails.
void writeUsdMesh(const MeshSequence& mesh, const std::filesystem::path& path);

}  // namespace sculpt
