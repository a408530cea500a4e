// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_topology.h
/// @brief The topology of a closed triangulated surface: its Euler characteristic and shells, and
///        the distinct vertices it has. One type for the status bar's figures (SurfaceStatistics)
///        and for the tracked mesh's topology events (core/tracking).

#include <cstddef>

namespace sculpt {

struct SurfaceTopology {
    std::size_t vertices = 0;  ///< distinct, as in the welded mesh
    long long euler = 0;       ///< V - E + F, with E = 3F/2 (closed surface)
    std::size_t shells = 0;    ///< connected components

    /// The same topology (Euler characteristic and shells), however many vertices each has.
    bool sameAs(const SurfaceTopology& other) const { return euler == other.euler && shells == other.shells; }
};

}  // namespace sculpt
