#pragma once
/// @file gltf_morph_file.h
/// @brief A mesh of fixed connectivity whose vertices move, as a binary glTF 2.0 file (`.glb`):
///        one morph target per frame and an animation of their weights, which Blender imports
///        as animated shape keys and any glTF viewer plays.
///
/// The base mesh is the first frame; target k holds frame k's positions minus the base's, and
/// the animation sets target k's weight to 1 (the others 0) at time k / fps, interpolating
/// linearly between frames. Positions are float32, indices uint32, in one buffer.

#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

struct MorphSequenceMesh {
    std::string name = "morph";
    MeshArray<std::array<std::uint32_t, 3>> triangles;      ///< #F, counter-clockwise from outside
    std::vector<std::vector<std::array<float, 3>>> frames;  ///< per frame #V positions, >= 1 frame
    double framesPerSecond = 24.0;
};

/// Writes `mesh` as `.glb`, atomically. @throws InputError naming the file if its directory is
/// missing, the frames differ in size, a triangle names no vertex, or the write fails.
void writeGltfMorph(const MorphSequenceMesh& mesh, const std::filesystem::path& path);

}  // namespace sculpt
