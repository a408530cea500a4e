// SPDX-License-Identifier: Apache-2.0
// The edge hold on a relaxed sphere mesh: an edge pushed just past 2e is slid back inside the
// range by its neighbourhood, everything stays inside [e, 2e] and well shaped, only vertices near
// it move; an edge far past the range is left to the remesher.

#include "core/primitives/analytic_shapes.h"
#include "core/tracking/edge_hold.h"
#include "core/tracking/mesh_tracker.h"
#include "core/tracking/tracked_mesh_quality.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace sculpt {
namespace {

using openvdb::Vec3d;

constexpr double kRadius = 12.0;

/// The seeded mesh of a ball of radius kRadius (voxel 0.5), its normals and no fixed vertex.
struct SphereMesh {
    TrackedMesh mesh;
    std::vector<Vec3d> normals;
    std::vector<std::uint8_t> fixed;
    double e = 0.0;
};

SphereMesh seededSphere()
{
    const MeshTracker tracker(makeSphere(kRadius, 0.5));
    SphereMesh s{tracker.mesh(), {}, {}, tracker.edgeLength()};
    for (const Vec3d& p : s.mesh.positions) s.normals.push_back(p.unit());
    s.fixed.assign(s.mesh.positions.size(), 0);
    return s;
}

double lengthOf(const TrackedMesh& mesh, std::uint32_t a, std::uint32_t b)
{
    return (mesh.positions[a] - mesh.positions[b]).length();
}

/// The smallest angle of the triangles around a or b, degrees.
double smallestAngleAround(const TrackedMesh& mesh, std::uint32_t a, std::uint32_t b)
{
    double smallest = 180.0;
    for (const auto& t : mesh.triangles)
        if (std::count(t.begin(), t.end(), a) + std::count(t.begin(), t.end(), b) > 0)
            smallest = std::min(smallest,
                                smallestAngleDegrees(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
    return smallest;
}

/// Moves the ends of the longest edge apart along it, onto the sphere, until it is `stretched` e
/// long; returns its two vertices.
std::pair<std::uint32_t, std::uint32_t> stretchLongestEdge(SphereMesh& s, double stretched)
{
    std::pair<std::uint32_t, std::uint32_t> longest{0, 0};
    for (const auto& t : s.mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (lengthOf(s.mesh, t[k], t[(k + 1) % 3]) > lengthOf(s.mesh, longest.first, longest.second))
                longest = {t[k], t[(k + 1) % 3]};
    const auto [a, b] = longest;
    while (lengthOf(s.mesh, a, b) < stretched * s.e) {
        const Vec3d u = (s.mesh.positions[b] - s.mesh.positions[a]).unit() * (0.005 * s.e);
        s.mesh.positions[a] = (s.mesh.positions[a] - u).unit() * kRadius;
        s.mesh.positions[b] = (s.mesh.positions[b] + u).unit() * kRadius;
    }
    s.normals[a] = s.mesh.positions[a].unit();
    s.normals[b] = s.mesh.positions[b].unit();
    return longest;
}

/// Up to EdgeHold::kSweeps sweeps, the moved vertices projected onto the sphere after each;
/// returns every vertex moved.
std::vector<std::uint8_t> hold(SphereMesh& s)
{
    const EdgeMemory memory;  // nothing remembered: every edge judged by its length now
    EdgeHold hold(s.mesh, s.normals, s.fixed, memory, s.e);
    std::vector<std::uint8_t> moved(s.mesh.positions.size(), 0);
    for (int sweep = 0; sweep < EdgeHold::kSweeps; ++sweep) {
        const std::vector<std::uint32_t> list = hold.sweep();
        for (const std::uint32_t v : list) {
            s.mesh.positions[v] = s.mesh.positions[v].unit() * kRadius;
            s.normals[v] = s.mesh.positions[v].unit();
            moved[v] = 1;
        }
    }
    return moved;
}

TEST(EdgeHold, SlidesAnEdgeJustPastTwiceTheTargetBackIntoRange)
{
    SphereMesh s = seededSphere();
    const auto [a, b] = stretchLongestEdge(s, 2.05);
    ASSERT_GE(smallestAngleAround(s.mesh, a, b), 20.0);
    const TrackedMesh stretched = s.mesh;
    const std::vector<std::uint8_t> moved = hold(s);

    EXPECT_LE(lengthOf(s.mesh, a, b), 2.0 * s.e);
    const TrackedMeshQuality q = measureQuality(s.mesh);
    EXPECT_GE(q.shortestEdge, s.e);
    EXPECT_LE(q.longestEdge, 2.0 * s.e);
    EXPECT_GE(q.smallestAngle, 20.0);
    EXPECT_EQ(s.mesh.triangles, stretched.triangles);
    // The excess goes to the neighbourhood, not across the sphere.
    const Vec3d middle = 0.5 * (stretched.positions[a] + stretched.positions[b]);
    std::size_t count = 0;
    for (std::size_t v = 0; v < moved.size(); ++v) {
        if (!moved[v]) continue;
        ++count;
        EXPECT_LT((stretched.positions[v] - middle).length(), 4.0 * s.e) << "vertex " << v;
    }
    EXPECT_GE(count, 2u);
}

TEST(EdgeHold, LeavesAnEdgeFarPastTheRangeToTheRemesher)
{
    SphereMesh s = seededSphere();
    const auto [a, b] = stretchLongestEdge(s, 2.25);
    ASSERT_GE(smallestAngleAround(s.mesh, a, b), 20.0) << "well shaped: only its length keeps it from being held";
    const double before = lengthOf(s.mesh, a, b);
    const std::vector<std::uint8_t> moved = hold(s);
    EXPECT_EQ(lengthOf(s.mesh, a, b), before);
    EXPECT_EQ(std::count(moved.begin(), moved.end(), 1), 0);
}

}  // namespace
}  // namespace sculpt
