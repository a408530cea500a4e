#include "core/tracking/tracked_mesh.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

TrackedMesh TrackedMesh::of(const TriangleMesh& mesh)
{
    TrackedMesh tracked;
    tracked.positions.reserve(mesh.positions.size());
    for (const auto& p : mesh.positions) tracked.positions.emplace_back(p[0], p[1], p[2]);
    tracked.triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
    tracked.ids.resize(mesh.positions.size());
    for (std::uint32_t i = 0; i < tracked.ids.size(); ++i) tracked.ids[i] = i;
    tracked.nextId = std::uint32_t(tracked.ids.size());
    return tracked;
}

TriangleMesh TrackedMesh::triangleMesh() const
{
    TriangleMesh mesh;
    mesh.positions.reserve(positions.size());
    for (const auto& p : positions) mesh.positions.push_back({float(p.x()), float(p.y()), float(p.z())});
    mesh.triangles.assign(triangles.begin(), triangles.end());
    return mesh;
}

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

}  // namespace sculpt
