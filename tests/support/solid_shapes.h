// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file solid_shapes.h
/// @brief Solids the print tools are tested on (islands, thin walls, cuts seen from the front),
///        and the topology of a field's mesh.

#include "core/field/field_image.h"
#include "core/solids/prism_cut.h"

#include <cstddef>

namespace sculpt::test {

struct Topology {
    std::size_t shells;
    long euler;
    bool closedManifold;
};

/// The shells, Euler characteristic and closedness of the field's marching-cubes mesh.
Topology topologyOf(const FieldImage& field);

/// Two balls of radius 5 at x = -8 and x = 8 and twenty specks of radius 0.4 (0.27 mm^3 each)
/// scattered around them; voxel size 0.2.
FieldImage ballsAndSpecks();

/// A plate 20 x 20 x 2 (z from -1 to 1) with a fin 0.6 thick and 4 high standing on it at x = 0;
/// its near edge (y < -6) chamfered at 45 degrees underneath.
FieldImage plateWithFin(double voxelSize);

/// The exact signed distance to the box of half extents `half` centred at `centre`.
double boxDistance(const openvdb::Vec3d& p, const openvdb::Vec3d& centre, const openvdb::Vec3d& half);

/// The front view (looking down -z from the eye at z = 100, parallel rays) of the square from
/// (x0, y0) to (x1, y1).
ViewPrism frontSquare(double x0, double y0, double x1, double y1);

}  // namespace sculpt::test
