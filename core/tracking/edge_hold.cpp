// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/edge_hold.h"

#include "core/tracking/mesh_adjacency.h"
#include "core/tracking/tracked_mesh_quality.h"

#include <algorithm>

namespace sculpt {

namespace {

using openvdb::Vec3d;

/// How far outside the range an edge may have been at the last step and still be held, in e.
constexpr double kWindow = 0.1;
constexpr double kSmallestAngleDegrees = 20.0;

}  // namespace

EdgeHold::EdgeHold(TrackedMesh& mesh, const std::vector<Vec3d>& normals, const std::vector<std::uint8_t>& fixed,
                   const EdgeMemory& memory, double edge)
    : mMesh(mesh), mNormals(normals), mFixed(fixed), mMemory(memory), mEdge(edge),
      mStars(VertexStars::of(mesh.triangles, mesh.positions.size()))
{
    mWellShaped.resize(mesh.positions.size());
    for (std::uint32_t v = 0; v < mWellShaped.size(); ++v) mWellShaped[v] = wellShapedAround(v, mesh.positions[v]);
}

std::vector<std::uint32_t> EdgeHold::sweep()
{
    const double shortest = (1.0 + kMargin) * mEdge, longest = 2.0 * (1.0 - kMargin) * mEdge;
    std::vector<std::uint8_t> moved(mMesh.positions.size(), 0);
    const auto slide = [&](std::uint32_t v, const Vec3d& d) {
        if (mFixed[v]) return;
        const Vec3d to = mMesh.positions[v] + d - mNormals[v] * mNormals[v].dot(d);
        if (!wellShapedAround(v, to)) return;
        mMesh.positions[v] = to;
        moved[v] = 1;
    };
    for (const auto& tri : mMesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
            if (a > b) continue;  // each edge once: a closed mesh has both its half-edges
            const Vec3d ab = mMesh.positions[b] - mMesh.positions[a];
            const double length = ab.length();
            if ((length >= shortest && length <= longest) || !held(a, b, length)) continue;
            // Each free end takes its share of the excess, along the edge within its tangent plane.
            const double excess = length - std::clamp(length, shortest, longest);
            const Vec3d share = ab / length * (mFixed[a] || mFixed[b] ? excess : 0.5 * excess);
            slide(a, share);
            slide(b, -share);
        }
    std::vector<std::uint32_t> list;
    for (std::uint32_t v = 0; v < moved.size(); ++v)
        if (moved[v]) list.push_back(v);
    return list;
}

bool EdgeHold::wellShapedAround(std::uint32_t v, const Vec3d& at) const
{
    for (std::uint32_t i = mStars.start[v]; i < mStars.start[v + 1]; ++i) {
        const auto& t = mMesh.triangles[mStars.list[i]];
        Vec3d p[3];
        for (int k = 0; k < 3; ++k) p[k] = t[k] == v ? at : mMesh.positions[t[k]];
        if ((p[1] - p[0]).cross(p[2] - p[0]).dot(mNormals[v]) <= 0.0) return false;
        if (smallestAngleDegrees(p[0], p[1], p[2]) < kSmallestAngleDegrees) return false;
    }
    return true;
}

bool EdgeHold::held(std::uint32_t a, std::uint32_t b, double length) const
{
    if ((mFixed[a] && mFixed[b]) || !mWellShaped[a] || !mWellShaped[b]) return false;
    // An edge new since the last step is judged by its length now.
    const auto it = mMemory.lengths.find(edgeKey(mMesh.ids[a], mMesh.ids[b]));
    const double was = it == mMemory.lengths.end() ? length : it->second;
    return was >= (1.0 - kWindow) * mEdge && was <= 2.0 * (1.0 + kWindow) * mEdge;
}

}  // namespace sculpt
