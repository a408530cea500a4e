// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/tracked_mesh_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculpt {

double smallestAngleDegrees(const openvdb::Vec3d& a, const openvdb::Vec3d& b, const openvdb::Vec3d& c)
{
    const auto angle = [](const openvdb::Vec3d& at, const openvdb::Vec3d& p, const openvdb::Vec3d& q) {
        const openvdb::Vec3d u = p - at, v = q - at;
        const double lengths = u.length() * v.length();
        return lengths > 0.0 ? std::acos(std::clamp(u.dot(v) / lengths, -1.0, 1.0)) : 0.0;
    };
    const double smallest = std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
    return smallest * 180.0 / M_PI;
}

TrackedMeshQuality measureQuality(const TrackedMesh& mesh)
{
    TrackedMeshQuality q{mesh.positions.size(), mesh.triangles.size()};
    if (mesh.triangles.empty()) return q;
    std::size_t below = 0;
    q.shortestEdge = std::numeric_limits<double>::max();
    for (const auto& t : mesh.triangles) {
        const double angle = smallestAngleDegrees(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
        q.smallestAngle = std::min(q.smallestAngle, angle);
        below += angle < 20.0;
        for (int k = 0; k < 3; ++k) {
            const double length = (mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).length();
            q.shortestEdge = std::min(q.shortestEdge, length);
            q.longestEdge = std::max(q.longestEdge, length);
        }
    }
    q.belowTwentyDegrees = double(below) / double(mesh.triangles.size());
    return q;
}

}  // namespace sculpt
