// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/tracked_sequence.h"

#include "core/tracking/mesh_adjacency.h"

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <utility>

namespace sculpt {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

constexpr std::size_t kLongestChain = 64;  // flat triangles between the two sides of a split edge, at most

/// The same triangle starting at its smallest vertex (orientation kept), to compare lists.
Triangle canonical(const Triangle& t)
{
    const int k = int(std::min_element(t.begin(), t.end()) - t.begin());
    return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}

std::array<float, 3> toFloat(const openvdb::Vec3d& p) { return {float(p.x()), float(p.y()), float(p.z())}; }

/// The last segment's connectivity with a frame's edits replayed onto it; vertices are indices
/// into its ids, and a merged vertex keeps its place, riding on its keeper.
class Replay {
public:
    Replay(const TrackedSegment& segment, const std::vector<std::uint32_t>& keepers)
        : triangles(segment.triangles), ids(segment.ids), keeper(keepers), mRiders(keepers.size())
    {
        for (std::uint32_t v = 0; v < ids.size(); ++v) {
            mIndex[ids[v]] = v;
            mRiders[keeper[v]].push_back(v);
        }
        for (std::uint32_t t = 0; t < triangles.size(); ++t) linkHalfEdges(t);
    }

    /// False when the edit does not fit this connectivity (then it is left half changed).
    bool apply(const MeshEdit& edit)
    {
        return edit.kind == MeshEdit::Kind::Split ? split(edit.a, edit.b, edit.born) : collapse(edit.a, edit.b);
    }

    std::vector<Triangle> triangles;
    std::vector<std::uint32_t> ids, keeper;
    /// The id of the next vertex only the segment has (TrackedSequence::kFirstExportOnlyId, down).
    std::uint32_t nextExportOnlyId = 0;
    /// Per vertex a split added, its edge's ends: it was at their midpoint in the frames before.
    std::vector<std::array<std::uint32_t, 2>> bornOn;

private:
    /// The index of the vertex of this id when it is not merged into another.
    std::optional<std::uint32_t> kept(std::uint32_t id) const
    {
        const auto it = mIndex.find(id);
        if (it == mIndex.end() || keeper[it->second] != it->second) return std::nullopt;
        return it->second;
    }

    bool flat(std::uint32_t t) const
    {
        const Triangle& tri = triangles[t];
        return keeper[tri[0]] == keeper[tri[1]] || keeper[tri[1]] == keeper[tri[2]] || keeper[tri[0]] == keeper[tri[2]];
    }

    /// The half-edge x -> y of a triangle of some area, x riding on a and y on b: the tracked
    /// edge a -> b.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> halfEdge(std::uint32_t a, std::uint32_t b) const
    {
        for (const std::uint32_t x : mRiders[a])
            for (const std::uint32_t y : mRiders[b]) {
                const auto it = mHalfEdges.find(halfEdgeKey(x, y));
                if (it != mHalfEdges.end() && !flat(it->second)) return std::make_pair(x, y);
            }
        return std::nullopt;
    }

    void linkHalfEdges(std::uint32_t t)
    {
        for (int k = 0; k < 3; ++k) mHalfEdges[halfEdgeKey(triangles[t][k], triangles[t][(k + 1) % 3])] = t;
    }
    void unlinkHalfEdges(std::uint32_t t)
    {
        for (int k = 0; k < 3; ++k) mHalfEdges.erase(halfEdgeKey(triangles[t][k], triangles[t][(k + 1) % 3]));
    }

    std::uint32_t opposite(std::uint32_t t, std::uint32_t x, std::uint32_t y) const
    {
        for (const std::uint32_t v : triangles[t])
            if (v != x && v != y) return v;
        return x;
    }

    /// As the remesher splits edge a -> b of (a, b, c) and b -> a of (b, a, d): (a, m, c), (m, b, c),
    /// (b, m, d) and (m, a, d). Where collapses merged edges into (a, b), flat triangles lie
    /// between the two here, and every merged edge is split, by m or by a vertex riding on it.
    bool split(std::uint32_t aId, std::uint32_t bId, std::uint32_t bornId)
    {
        const auto a = kept(aId), b = kept(bId);
        if (!a || !b || mIndex.count(bornId)) return false;
        const auto first = halfEdge(*a, *b);
        if (!first) return false;
        // The half-edges x -> y along a -> b, from the triangle holding the first, across the flat
        // triangles (each holding the last one's twin and the next), to the one holding b -> a.
        std::vector<std::pair<std::uint32_t, std::uint32_t>> chain{*first};
        std::vector<std::uint32_t> flats;
        std::uint32_t last = 0;
        for (;;) {
            const auto [x, y] = chain.back();
            const auto twin = mHalfEdges.find(halfEdgeKey(y, x));
            if (twin == mHalfEdges.end()) return false;
            last = twin->second;
            if (!flat(last)) break;
            if (flats.size() > kLongestChain) return false;
            flats.push_back(last);
            const std::uint32_t r = opposite(last, y, x);
            if (keeper[r] == *b) chain.emplace_back(x, r);
            else if (keeper[r] == *a) chain.emplace_back(r, y);
            else return false;
        }
        splitChain(chain, flats, mHalfEdges.at(halfEdgeKey(chain[0].first, chain[0].second)), last, bornId);
        return true;
    }

    /// Splits each chain edge at its midpoint (the frames before), by m and by vertices riding on
    /// m: t1 (x0, y0, c) into (x0, m0, c), (m0, y0, c); t2 (yk, xk, d) into (yk, mk, d), (mk, xk, d);
    /// each flat triangle, split on its two chain edges, into three, all flat once they ride on m.
    void splitChain(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& chain,
                    const std::vector<std::uint32_t>& flats, std::uint32_t t1, std::uint32_t t2, std::uint32_t bornId)
    {
        std::vector<std::uint32_t> m;
        const auto m0 = std::uint32_t(ids.size());
        for (const auto& [x, y] : chain) {
            m.push_back(std::uint32_t(ids.size()));
            ids.push_back(m.size() == 1 ? bornId : nextExportOnlyId--);
            mIndex[ids.back()] = m.back();
            keeper.push_back(m0);
            mRiders.emplace_back();
            mRiders[m0].push_back(m.back());
            bornOn.push_back({x, y});
        }
        for (const std::uint32_t t : flats) unlinkHalfEdges(t);
        unlinkHalfEdges(t1);
        unlinkHalfEdges(t2);
        const std::size_t added = triangles.size();
        const auto [x0, y0] = chain.front();
        const auto [xk, yk] = chain.back();
        const std::uint32_t c = opposite(t1, x0, y0), d = opposite(t2, yk, xk);
        triangles[t1] = {x0, m.front(), c};
        triangles.push_back({m.front(), y0, c});
        triangles[t2] = {yk, m.back(), d};
        triangles.push_back({m.back(), xk, d});
        for (std::size_t j = 0; j < flats.size(); ++j) {
            const auto [x, y] = chain[j];
            const std::uint32_t f = flats[j], r = opposite(f, y, x), mA = m[j], mB = m[j + 1];
            if (chain[j + 1].first == x) {  // (y, x, r) split on (y, x) and (x, r)
                triangles[f] = {mA, x, mB};
                triangles.push_back({y, mA, mB});
                triangles.push_back({y, mB, r});
            } else {  // split on (y, x) and (r, y)
                triangles[f] = {mB, y, mA};
                triangles.push_back({mA, x, r});
                triangles.push_back({mA, r, mB});
            }
        }
        for (const std::uint32_t t : flats) linkHalfEdges(t);
        linkHalfEdges(t1);
        linkHalfEdges(t2);
        for (std::size_t t = added; t < triangles.size(); ++t) linkHalfEdges(std::uint32_t(t));
    }

    /// `goneId` and everything riding on it ride on `keptId` from now on.
    bool collapse(std::uint32_t keptId, std::uint32_t goneId)
    {
        const auto a = kept(keptId), b = kept(goneId);
        if (!a || !b || *a == *b) return false;
        for (const std::uint32_t v : mRiders[*b]) keeper[v] = *a;
        mRiders[*a].insert(mRiders[*a].end(), mRiders[*b].begin(), mRiders[*b].end());
        mRiders[*b].clear();
        return true;
    }

    std::vector<std::vector<std::uint32_t>> mRiders;  // per kept vertex, the vertices riding on it (itself too)
    std::unordered_map<std::uint32_t, std::uint32_t> mIndex;
    std::unordered_map<std::uint64_t, std::uint32_t> mHalfEdges;  // directed edge -> its triangle
};

/// Each vertex's index in `frame` (a merged vertex: its keeper's), when the replayed mesh's
/// kept vertices are the frame's and its triangles of some area are the frame's triangles.
std::optional<std::vector<std::uint32_t>> matchFrame(const Replay& replay, const TrackedMesh& frame)
{
    std::unordered_map<std::uint32_t, std::uint32_t> frameIndex;
    for (std::uint32_t v = 0; v < frame.ids.size(); ++v) frameIndex[frame.ids[v]] = v;
    std::size_t kept = 0;
    std::vector<std::uint32_t> at(replay.ids.size());
    for (std::size_t v = 0; v < at.size(); ++v) {
        const auto it = frameIndex.find(replay.ids[replay.keeper[v]]);
        if (it == frameIndex.end()) return std::nullopt;
        at[v] = it->second;
        kept += replay.keeper[v] == v;
    }
    if (kept != frame.ids.size()) return std::nullopt;
    std::vector<Triangle> replayed, truth;
    for (const Triangle& t : replay.triangles) {
        const Triangle m{at[t[0]], at[t[1]], at[t[2]]};
        if (m[0] != m[1] && m[1] != m[2] && m[0] != m[2]) replayed.push_back(canonical(m));
    }
    for (const Triangle& t : frame.triangles) truth.push_back(canonical(t));
    std::sort(replayed.begin(), replayed.end());
    std::sort(truth.begin(), truth.end());
    if (replayed != truth) return std::nullopt;
    return at;
}

}  // namespace

TriangleMesh TrackedSegment::frameMesh(std::size_t frame) const
{
    TriangleMesh mesh;
    mesh.positions.assign(positions.at(frame).begin(), positions.at(frame).end());
    mesh.triangles.assign(triangles.begin(), triangles.end());
    return mesh;
}

void TrackedSequence::add(const TrackedMesh& frame, const std::vector<MeshEdit>& edits)
{
    if (mSegments.empty() || !extend(frame, edits)) start(frame);
    ++mFrames;
}

void TrackedSequence::start(const TrackedMesh& frame)
{
    TrackedSegment segment;
    segment.firstFrame = mFrames;
    segment.triangles = frame.triangles;
    segment.ids = frame.ids;
    std::vector<std::array<float, 3>> points;
    points.reserve(frame.positions.size());
    for (const auto& p : frame.positions) points.push_back(toFloat(p));
    segment.positions.push_back(std::move(points));
    mSegments.push_back(std::move(segment));
    mKeeper.resize(frame.ids.size());
    for (std::uint32_t v = 0; v < mKeeper.size(); ++v) mKeeper[v] = v;
}

bool TrackedSequence::extend(const TrackedMesh& frame, const std::vector<MeshEdit>& edits)
{
    TrackedSegment& segment = mSegments.back();
    Replay replay(segment, mKeeper);
    replay.nextExportOnlyId = mNextExportOnlyId;
    for (const MeshEdit& edit : edits)
        if (!replay.apply(edit)) return false;
    std::size_t merged = 0;
    for (std::uint32_t v = 0; v < replay.keeper.size(); ++v) merged += replay.keeper[v] != v;
    if (double(merged) > kMostMerged * double(replay.ids.size())) return false;
    const auto at = matchFrame(replay, frame);
    if (!at) return false;
    // A vertex a split made was at its edge's midpoint in the frames before.
    for (auto& points : segment.positions)
        for (const auto& [x, y] : replay.bornOn)
            points.push_back({0.5f * (points[x][0] + points[y][0]), 0.5f * (points[x][1] + points[y][1]),
                              0.5f * (points[x][2] + points[y][2])});
    std::vector<std::array<float, 3>> points;
    points.reserve(at->size());
    for (const std::uint32_t v : *at) points.push_back(toFloat(frame.positions[v]));
    segment.positions.push_back(std::move(points));
    segment.triangles = std::move(replay.triangles);
    segment.ids = std::move(replay.ids);
    mKeeper = std::move(replay.keeper);
    mNextExportOnlyId = replay.nextExportOnlyId;
    return true;
}

}  // namespace sculpt
