// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/topology_surgery.h"

#include "core/tracking/mesh_adjacency.h"
#include "core/tracking/surface_projection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace sculpt {

namespace {

using openvdb::Vec3d;
using Triangle = std::array<std::uint32_t, 3>;

constexpr double kPairVoxels = 3.0;  // how far apart two contradicted sheets' vertices may be
constexpr double kOpposed = 0.5;     // cosines: normals against each other, along the pair
// |phi| at a triangle's centroid, in voxels, over which it spans no surface: the loosest first,
// tighter where the cut it gives does not separate what the field separates (a band across a
// crease whose triangles bend over the gap only a little).
constexpr std::array<double, 3> kOffSurfaceVoxels = {0.75, 0.5, 0.3};
constexpr int kCleanPasses = 4;        // of cutting more where two borders touch
constexpr std::size_t kGrowRings = 2;  // of widening a cut that did not give the field's topology

/// Vertices by grid cell of side `cell`, to find the ones near a point.
class VertexHash {
public:
    VertexHash(const std::vector<Vec3d>& points, double cell) : mPoints(points), mCell(cell)
    {
        for (std::uint32_t v = 0; v < points.size(); ++v) mCells[key(cellOf(points[v]))].push_back(v);
    }

    /// Calls `visit(w)` for every vertex in the 27 cells around `p`.
    template <typename Visit>
    void around(const Vec3d& p, Visit visit) const
    {
        const openvdb::Coord c = cellOf(p);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = mCells.find(key(c.offsetBy(dx, dy, dz)));
                    if (it != mCells.end())
                        for (const std::uint32_t w : it->second) visit(w);
                }
    }

private:
    openvdb::Coord cellOf(const Vec3d& p) const
    {
        return openvdb::Coord(int(std::floor(p.x() / mCell)), int(std::floor(p.y() / mCell)),
                              int(std::floor(p.z() / mCell)));
    }
    static std::uint64_t key(const openvdb::Coord& c)
    {
        const auto part = [](int v) { return std::uint64_t(std::uint32_t(v) & 0x1FFFFF); };
        return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
    }

    const std::vector<Vec3d>& mPoints;
    double mCell;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> mCells;
};

/// Each vertex's neighbours, sorted.
std::vector<std::vector<std::uint32_t>> neighbourLists(const TrackedMesh& mesh)
{
    std::vector<std::vector<std::uint32_t>> lists(mesh.positions.size());
    for (const Triangle& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) lists[t[k]].push_back(t[(k + 1) % 3]);
    for (auto& list : lists) std::sort(list.begin(), list.end());
    return lists;
}

/// The vertices where the mesh contradicts the field (see the header): pairs of sheets joined or
/// parted, the same surface covered twice, triangles off the surface, points left quasi-critical.
std::vector<std::uint32_t> eventVertices(const TrackedMesh& mesh, const std::vector<Vec3d>& normals,
                                         const std::vector<std::uint8_t>& quasiCritical, const FieldImage& field,
                                         double offSurfaceVoxels)
{
    const double h = field.voxelSize(), reach = kPairVoxels * h;
    const VertexHash hash(mesh.positions, reach);
    const FieldProbe probe(field.grid());
    const auto neighbours = neighbourLists(mesh);
    std::vector<std::uint8_t> marked(mesh.positions.size(), 0);
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3d &p = mesh.positions[v], &n = normals[v];
        if (v < quasiCritical.size() && quasiCritical[v]) marked[v] = 1;
        hash.around(p, [&](std::uint32_t w) {
            if (w <= v) return;
            const Vec3d d = mesh.positions[w] - p;
            const double length = d.length();
            if (length > reach || length < 1e-12) return;
            const double facing = n.dot(normals[w]);
            if (facing > kOpposed && length < h && !std::binary_search(neighbours[v].begin(), neighbours[v].end(), w)) {
                marked[v] = marked[w] = 1;  // the same surface covered by two sheets of the mesh
                return;
            }
            if (facing > -kOpposed) return;
            const double along = n.dot(d) / length, back = -normals[w].dot(d) / length;
            const double midway = probe.at(p + 0.5 * d).phi;
            const bool joined = along > kOpposed && back > kOpposed && midway < 0.0;    // facing, solid between
            const bool parted = along < -kOpposed && back < -kOpposed && midway > 0.0;  // back to back, air between
            if (joined || parted) marked[v] = marked[w] = 1;
        });
    }
    for (const Triangle& t : mesh.triangles) {
        const Vec3d centroid = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
        if (std::abs(probe.at(centroid).phi) > offSurfaceVoxels * h) {
            for (const std::uint32_t v : t) marked[v] = 1;
        }
    }
    std::vector<std::uint32_t> list;
    for (std::uint32_t v = 0; v < marked.size(); ++v)
        if (marked[v]) list.push_back(v);
    return list;
}

/// The triangles touching a vertex of `region`.
std::vector<std::uint8_t> trianglesToCut(const TrackedMesh& mesh, const std::vector<std::uint8_t>& region)
{
    std::vector<std::uint8_t> cut(mesh.triangles.size(), 0);
    for (std::size_t t = 0; t < cut.size(); ++t)
        for (const std::uint32_t v : mesh.triangles[t]) cut[t] |= region[v];
    return cut;
}

struct BorderLoops {
    /// Each as the vertices of the half-edges a closing triangle must hold (the reverse of the
    /// border's), in order.
    std::vector<std::vector<std::uint32_t>> loops;
    /// Vertices where two borders touch: the loops are not simple while there are any.
    std::vector<std::uint32_t> pinched;
};

BorderLoops borderLoops(const std::vector<Triangle>& triangles)
{
    std::unordered_set<std::uint64_t> present;
    for (const Triangle& t : triangles)
        for (int k = 0; k < 3; ++k) present.insert(halfEdgeKey(t[k], t[(k + 1) % 3]));
    BorderLoops found;
    std::unordered_map<std::uint32_t, std::uint32_t> next;
    for (const Triangle& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            if (!present.count(halfEdgeKey(b, a)) && !next.emplace(b, a).second) found.pinched.push_back(b);
        }
    if (!found.pinched.empty()) return found;
    std::vector<std::uint32_t> starts;
    for (const auto& [from, to] : next) starts.push_back(from);
    std::sort(starts.begin(), starts.end());  // deterministic
    std::unordered_set<std::uint32_t> visited;
    for (const std::uint32_t start : starts) {
        if (visited.count(start)) continue;
        std::vector<std::uint32_t> loop;
        for (std::uint32_t v = start; !visited.count(v); v = next.at(v)) {
            visited.insert(v);
            loop.push_back(v);
        }
        found.loops.push_back(std::move(loop));
    }
    return found;
}

/// A strip joining loop p (walked forwards) to loop q (walked backwards), at each step taking
/// the shorter new diagonal; consistent with the loops' orientation (see borderLoops).
void bridge(const std::vector<Vec3d>& x, const std::vector<std::uint32_t>& p, const std::vector<std::uint32_t>& q,
            std::vector<Triangle>& out)
{
    const std::size_t n = p.size(), m = q.size();
    std::size_t j = 0;
    for (std::size_t k = 1; k < m; ++k)
        if ((x[q[k]] - x[p[0]]).lengthSqr() < (x[q[j]] - x[p[0]]).lengthSqr()) j = k;
    const auto qAt = [&](std::size_t steps) { return q[(j + m - steps % m) % m]; };
    std::size_t i = 0, back = 0;
    while (i < n || back < m) {
        const std::uint32_t pi = p[i % n], pn = p[(i + 1) % n], qj = qAt(back), qp = qAt(back + 1);
        const bool advanceP = back == m || (i < n && (x[pn] - x[qj]).lengthSqr() <= (x[pi] - x[qp]).lengthSqr());
        if (advanceP) {
            out.push_back({pi, pn, qj});
            ++i;
        } else {
            out.push_back({qj, pi, qp});
            ++back;
        }
    }
}

Vec3d centroidOf(const std::vector<Vec3d>& x, const std::vector<std::uint32_t>& loop)
{
    Vec3d sum(0.0);
    for (const std::uint32_t v : loop) sum += x[v];
    return sum / double(loop.size());
}

/// The loops in pairs, nearest centroids first (several holes can open in one step).
std::vector<std::pair<std::size_t, std::size_t>> nearestPairs(const std::vector<Vec3d>& x,
                                                              const std::vector<std::vector<std::uint32_t>>& loops)
{
    std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
    for (std::size_t a = 0; a < loops.size(); ++a)
        for (std::size_t b = a + 1; b < loops.size(); ++b)
            candidates.emplace_back((centroidOf(x, loops[a]) - centroidOf(x, loops[b])).length(), a, b);
    std::sort(candidates.begin(), candidates.end());
    std::vector<std::uint8_t> taken(loops.size(), 0);
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (const auto& [distance, a, b] : candidates)
        if (!taken[a] && !taken[b]) {
            taken[a] = taken[b] = 1;
            pairs.emplace_back(a, b);
        }
    return pairs;
}

/// Closes `loop` by a fan around a new vertex at its centroid.
void cap(TrackedMesh& mesh, const std::vector<std::uint32_t>& loop, std::vector<Triangle>& out)
{
    const auto c = std::uint32_t(mesh.positions.size());
    mesh.positions.push_back(centroidOf(mesh.positions, loop));
    mesh.ids.push_back(mesh.nextId++);
    for (std::size_t k = 0; k < loop.size(); ++k) out.push_back({loop[k], loop[(k + 1) % loop.size()], c});
}

/// `mesh` with the triangles on `region` cut away (more where two borders would touch, until
/// the loops are simple) and the loops closed as `surgery.kind` says; nothing when the result
/// is not a closed, oriented 2-manifold of topology `truth`. Fills `surgery`'s counts.
std::optional<TrackedMesh> cutAndClose(const TrackedMesh& mesh, std::vector<std::uint8_t> region,
                                       const SurfaceTopology& truth, Surgery& surgery)
{
    TrackedMesh result = mesh;
    BorderLoops border;
    for (int pass = 0; pass < kCleanPasses; ++pass) {
        const std::vector<std::uint8_t> cut = trianglesToCut(mesh, region);
        result.triangles.clear();
        for (std::size_t t = 0; t < cut.size(); ++t)
            if (!cut[t]) result.triangles.push_back(mesh.triangles[t]);
        border = borderLoops(result.triangles);
        if (border.pinched.empty()) break;
        for (const std::uint32_t v : border.pinched) region[v] = 1;
    }
    const std::vector<std::vector<std::uint32_t>>& loops = border.loops;
    if (!border.pinched.empty() || loops.empty()) return std::nullopt;
    for (const auto& loop : loops)
        if (loop.size() < 3) return std::nullopt;
    surgery.addedVertices = 0;
    if (surgery.kind == SurgeryKind::Bridge) {
        if (loops.size() % 2 != 0) return std::nullopt;
        for (const auto& [p, q] : nearestPairs(result.positions, loops))
            bridge(result.positions, loops[p], loops[q], result.triangles);
    } else {
        for (const auto& loop : loops) cap(result, loop, result.triangles);
        surgery.addedVertices = loops.size();
    }
    surgery.loops = loops.size();
    const std::size_t closed = result.positions.size();
    result.dropUnusedVertices();
    surgery.removedVertices = closed - result.positions.size();
    if (!closedOrientedManifold(result.triangles) ||
        !surfaceTopology(result.triangles, result.positions.size()).sameAs(truth))
        return std::nullopt;
    return result;
}

}  // namespace

bool closedOrientedManifold(const std::vector<Triangle>& triangles)
{
    std::unordered_set<std::uint64_t> edges;
    for (const Triangle& t : triangles)
        for (int k = 0; k < 3; ++k)
            if (t[k] == t[(k + 1) % 3] || !edges.insert(halfEdgeKey(t[k], t[(k + 1) % 3])).second) return false;
    for (const std::uint64_t e : edges)
        if (!edges.count((e << 32) | (e >> 32))) return false;
    return true;
}

Surgery operateOnTopology(TrackedMesh& mesh, const std::vector<Vec3d>& normals,
                          const std::vector<std::uint8_t>& quasiCritical, const FieldImage& field,
                          const SurfaceTopology& truth)
{
    const SurfaceTopology now = surfaceTopology(mesh.triangles, mesh.positions.size());
    if (truth.euler == now.euler) return {};
    const std::vector<std::uint32_t> event = eventVertices(mesh, normals, quasiCritical, field, kOffSurfaceVoxels[0]);
    if (event.empty()) return {};
    Surgery surgery;
    surgery.kind = truth.euler < now.euler ? SurgeryKind::Bridge : SurgeryKind::Cap;
    for (const std::uint32_t v : event) surgery.centre += mesh.positions[v] / double(event.size());
    for (const std::uint32_t v : event)
        surgery.radius = std::max(surgery.radius, (mesh.positions[v] - surgery.centre).length());

    const auto neighbours = neighbourLists(mesh);
    std::vector<std::uint8_t> region(mesh.positions.size(), 0);
    for (std::size_t attempt = 0; attempt < kOffSurfaceVoxels.size() + kGrowRings; ++attempt) {
        if (attempt < kOffSurfaceVoxels.size()) {
            const std::vector<std::uint32_t> marks =
                attempt == 0 ? event : eventVertices(mesh, normals, quasiCritical, field, kOffSurfaceVoxels[attempt]);
            for (const std::uint32_t v : marks) region[v] = 1;
        } else {  // the marks still miss part of the event: a ring wider all round
            std::vector<std::uint8_t> grown = region;
            for (std::uint32_t v = 0; v < region.size(); ++v)
                if (region[v])
                    for (const std::uint32_t w : neighbours[v]) grown[w] = 1;
            region = std::move(grown);
        }
        if (std::optional<TrackedMesh> result = cutAndClose(mesh, region, truth, surgery)) {
            mesh = std::move(*result);
            return surgery;
        }
    }
    return {};
}

}  // namespace sculpt
