// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file gltf_morph_file.h
/// @brief A mesh of fixed connectivity whose vertices move, as a binary glTF 2.0 file (`.glb`):
///        one morph target per frame and an animation of their weights, which Blender imports
///        as animated shape keys and any glTF viewer plays.
///
/// The base mesh is the first frame; target k holds frame k's positions minus the base's, and
/// the animation sets target k's weight to 1 (the others 0) at time k / fps, interpolating
/// linearly between frames. Positions are float32, indices uint32, in one buffer.

#include "core/io/mesh_sequence.h"

namespace sculpt {

/// Writes `mesh` as `.glb`, atomically (its first frame number and ids are not written: glTF has
/// no place for them). @throws InputError naming the file if its directory is missing, the
/// sequence is malformed (checkMeshSequence) or the write fails.
void writeGltfMorph(const MeshSequence& mesh, const std::filesystem::path& path);

}  // namespace sculpt
