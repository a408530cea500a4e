// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file tracked_mesh_quality.h
/// @brief How well shaped a tracked mesh is, measured: its smallest angle, the share of thin
///        triangles, its shortest and longest edges.

#include "core/tracking/tracked_mesh.h"

namespace sculpt {

/// The smallest angle of a triangle, in degrees (0 for a degenerate one).
double smallestAngleDegrees(const openvdb::Vec3d& a, const openvdb::Vec3d& b, const openvdb::Vec3d& c);

/// How well shaped a tracked mesh is: what the tracker promises (edges within [e, 2e], few
/// triangles under 20 degrees) measured.
struct TrackedMeshQuality {
    std::size_t vertices = 0, triangles = 0;
    double smallestAngle = 180.0;                  ///< degrees, over all triangles
    double belowTwentyDegrees = 0.0;               ///< share of triangles
    double shortestEdge = 0.0, longestEdge = 0.0;  ///< world units
};
TrackedMeshQuality measureQuality(const TrackedMesh& mesh);

}  // namespace sculpt
