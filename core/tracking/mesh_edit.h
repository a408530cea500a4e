// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_edit.h
/// @brief A change of a tracked mesh's connectivity, by vertex ids: what a sequence replays to
///        keep one set of vertices and triangles over the frames around it (tracked_sequence.h).

#include <cstdint>

namespace sculpt {

struct MeshEdit {
    enum class Kind : std::uint8_t { Split, Collapse };
    Kind kind = Kind::Split;
    /// Split: edge a -> b of one triangle (b -> a of the other) gained vertex `born` at its midpoint.
    /// Collapse: b was merged into a (a moved; b and the two triangles on the edge are gone).
    std::uint32_t a = 0, b = 0, born = 0;
};

}  // namespace sculpt
