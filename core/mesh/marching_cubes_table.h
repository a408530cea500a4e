// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file marching_cubes_table.h
/// @brief The marching-cubes case table, generated so that it is consistent across cells.
///
/// Cube corners are numbered by their offset bits: corner c sits at (c&1, c>>1&1, c>>2&1).
/// Edge e joins corner `edgeCorner(e)` to `edgeCorner(e) + (1 << edgeAxis(e))`. A corner is
/// *inside* when its value is below the iso-value (a value equal to the iso-value is outside:
/// one rule everywhere).
///
/// The table is not typed in from a paper: it is built at start-up by tracing, for each of the
/// 256 sign configurations, the closed loops that the iso-curves draw on the six faces of the
/// cube, then fanning each loop into triangles (the construction of Lorensen & Cline's cases as
/// described in the marching-cubes slides, with faces decided consistently). A face whose
/// diagonal corners share a sign while neighbours differ is *ambiguous*; it is resolved by the
/// asymptotic decider (Nielson & Hamann 1991): the two inside corners are joined across the face
/// iff the bilinear saddle is inside, i.e. iff f(a) f(c) > f(b) f(d) with (a, c) the inside
/// diagonal, values taken relative to the iso-value. The decision depends only on the face's four
/// values, so the two cells sharing a face decide alike and the welded surface of a closed level
/// set is a closed, consistently oriented 2-manifold. A configuration with k ambiguous faces has
/// 2^k triangulations, selected at run time by the k decision bits.

#include <array>
#include <cstdint>

namespace sculpt::mc {

/// Axis (0 x, 1 y, 2 z) along which edge `e` (0..11) runs.
constexpr int edgeAxis(int e) { return e / 4; }
/// Lower corner of edge `e`: the corner with a 0 bit on the edge's axis.
int edgeCorner(int e);

/// One face of the cube, its corners listed in a cyclic order that depends only on the face's
/// axis, so two cells sharing the face list the same points in the same order.
struct Face {
    int axis;                    ///< the face's normal axis
    int side;                    ///< 0: at the low coordinate, 1: at the high coordinate
    std::array<int, 4> corners;  ///< cyclic
};
const Face& face(int f);

/// Pseudo edge index of a vertex at the centre of a loop (see Triangulation).
constexpr int kCentre = 12;

/// Triangles of one case, as edge indices, counter-clockwise seen from outside. A loop is
/// triangulated without diagonals lying in a face that the neighbouring cell might also draw;
/// the few loops (of 7 or more vertices) where that is impossible are fanned around an extra
/// vertex, kCentre, placed at the mean of `centreLoop`. 12 vertices give at most 12 triangles.
struct Triangulation {
    std::uint8_t triangleCount = 0;
    std::array<std::array<std::uint8_t, 3>, 12> edges{};
    std::uint8_t centreLoopSize = 0;
    std::array<std::uint8_t, 12> centreLoop{};  ///< edges whose vertices the centre averages
};

/// All triangulations of one sign configuration.
struct Case {
    std::uint8_t ambiguousFaceCount = 0;
    std::array<std::uint8_t, 6> ambiguousFaces{};  ///< indices into face()
    bool mayUseCentre = false;                     ///< some triangulation of this case has a centre vertex
    /// Triangulation for the decision bits `bits` (bit k: ambiguous face k joins its inside
    /// corners).
    const Triangulation& triangulation(unsigned bits) const;

    std::uint32_t firstEntry = 0;  ///< internal: offset of bits == 0 in the entry table
};

/// The case for a configuration: bit c of `cubeIndex` set iff corner c is inside. The 256 cases
/// are contiguous: &cubeCase(0) + i is case i.
const Case& cubeCase(unsigned cubeIndex);

/// True if the inside corners of an ambiguous face join across it, for the face's corner
/// values relative to the iso-value listed in face order (see the file comment).
inline bool insideCornersJoin(float v0, float v1, float v2, float v3)
{
    const float p02 = v0 * v2, p13 = v1 * v3;
    return v0 < 0.0f ? p02 > p13 : p13 > p02;
}

}  // namespace sculpt::mc
