// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_sequence.h
/// @brief A mesh of fixed connectivity whose vertices move: what the sequence writers (glTF
///        morph targets, USD time samples) take, one tracked segment at a time.

#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

struct MeshSequence {
    std::string name = "morph";
    MeshArray<std::array<std::uint32_t, 3>> triangles;      ///< #F, counter-clockwise from outside
    std::vector<std::vector<std::array<float, 3>>> frames;  ///< per frame #V positions, >= 1 frame
    double framesPerSecond = 24.0;
    int firstFrame = 0;              ///< the frame number of frames[0] in the whole sequence
    std::vector<std::uint32_t> ids;  ///< #V stable vertex ids, or empty
};

/// @throws InputError naming `path` if there is no frame, the frames differ in size, a triangle
/// names no vertex, or ids are given but not one per vertex.
void checkMeshSequence(const MeshSequence& mesh, const std::filesystem::path& path);

}  // namespace sculpt
