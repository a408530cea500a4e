// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/edge_remesher.h"

#include "core/tracking/mesh_adjacency.h"

#include <algorithm>
#include <cstdlib>
#include <tuple>

namespace sculpt {

namespace {

using openvdb::Vec3d;

constexpr double kRateTolerance = 0.1;  // of e: an edge changing faster is left to move
constexpr int kPasses = 3;              // of splits, then of collapses, per step

struct Edge {
    std::uint32_t a, b;  // vertex indices
    double length;
};

class Remesher {
public:
    Remesher(TrackedMesh& mesh, EdgeMemory& memory, const std::vector<std::uint8_t>& inverted,
             const RemeshLimits& limits)
        : mMesh(mesh), mMemory(memory), mInverted(inverted), mE(limits.edge),
          mShortest(limits.shortest > 0.0 ? limits.shortest : limits.edge),
          mLongest(limits.longest > 0.0 ? limits.longest : 2.0 * limits.edge), mFlips(limits.flips)
    {
        mInverted.resize(mesh.triangles.size(), 0);
    }

    RemeshCounts run()
    {
        for (int pass = 0; pass < kPasses && splitPass(); ++pass) {}
        for (int pass = 0; pass < kPasses && collapsePass(); ++pass) {}
        compact();
        if (mFlips) flipPass();
        remember();
        return mCounts;
    }

private:
    double length(std::uint32_t a, std::uint32_t b) const { return (mMesh.positions[a] - mMesh.positions[b]).length(); }
    std::uint64_t key(std::uint32_t a, std::uint32_t b) const { return edgeKey(mMesh.ids[a], mMesh.ids[b]); }

    /// Each edge once (from its half-edge whose first vertex is the smaller index).
    std::vector<Edge> edges() const
    {
        std::vector<Edge> list;
        for (std::size_t t = 0; t < mMesh.triangles.size(); ++t) {
            if (mDeadTriangle.size() > t && mDeadTriangle[t]) continue;
            const auto& tri = mMesh.triangles[t];
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t u = tri[k], v = tri[(k + 1) % 3];
                if (u < v) list.push_back({u, v, length(u, v)});
            }
        }
        return list;
    }

    /// The length change since the last step (0 for an edge that did not exist then).
    double change(const Edge& e) const
    {
        const auto it = mMemory.lengths.find(key(e.a, e.b));
        return it == mMemory.lengths.end() ? 0.0 : e.length - it->second;
    }
    /// Changed at the last step, or already in this one.
    bool frozen(const Edge& e) const
    {
        const std::uint64_t k = key(e.a, e.b);
        return mMemory.frozen.count(k) > 0 || mFrozenNext.count(k) > 0;
    }

    bool splitPass()
    {
        std::vector<Edge> candidates;
        for (const Edge& e : edges())
            if (e.length > mLongest && !frozen(e) && change(e) >= -kRateTolerance * mE) candidates.push_back(e);
        if (candidates.empty()) return false;
        std::sort(candidates.begin(), candidates.end(), [this](const Edge& x, const Edge& y) {
            return std::make_tuple(-x.length, key(x.a, x.b)) < std::make_tuple(-y.length, key(y.a, y.b));
        });
        const HalfEdges triangleOf = halfEdges();
        std::vector<std::uint8_t> touched(mMesh.triangles.size(), 0);
        const std::size_t before = mCounts.splits;
        for (const Edge& e : candidates) {
            const auto ab = triangleOf.find(halfEdgeKey(e.a, e.b)), ba = triangleOf.find(halfEdgeKey(e.b, e.a));
            if (ab == triangleOf.end() || ba == triangleOf.end()) continue;  // not a closed edge
            const std::uint32_t t1 = ab->second, t2 = ba->second;
            if (touched[t1] || touched[t2] || mInverted[t1] || mInverted[t2]) continue;
            touched[t1] = touched[t2] = 1;
            split(e.a, e.b, t1, t2);
        }
        return mCounts.splits > before;
    }

    using HalfEdges = std::unordered_map<std::uint64_t, std::uint32_t>;  // directed half-edge -> triangle

    HalfEdges halfEdges() const
    {
        HalfEdges triangleOf;
        for (std::uint32_t t = 0; t < mMesh.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                triangleOf[halfEdgeKey(mMesh.triangles[t][k], mMesh.triangles[t][(k + 1) % 3])] = t;
        return triangleOf;
    }

    /// Flips each edge (a, b) whose flip to (c, d) brings the valences of a, b, c and d nearer 6,
    /// when (c, d) is not an edge yet, both new triangles face as the old ones did and (c, d)
    /// stays under 2e. Runs on a compacted mesh.
    void flipPass()
    {
        HalfEdges triangleOf = halfEdges();
        std::vector<int> valence(mMesh.positions.size(), 0);
        for (const auto& tri : mMesh.triangles)
            for (const std::uint32_t v : tri) ++valence[v];
        std::vector<std::uint8_t> touched(mMesh.triangles.size(), 0);
        for (const Edge& e : edges()) {
            const auto ab = triangleOf.find(halfEdgeKey(e.a, e.b)), ba = triangleOf.find(halfEdgeKey(e.b, e.a));
            if (ab == triangleOf.end() || ba == triangleOf.end()) continue;
            const std::uint32_t t1 = ab->second, t2 = ba->second, a = e.a, b = e.b;
            if (touched[t1] || touched[t2]) continue;
            const std::uint32_t c = opposite(t1, a, b), d = opposite(t2, a, b);
            if (c == d || triangleOf.count(halfEdgeKey(c, d)) || triangleOf.count(halfEdgeKey(d, c))) continue;
            const auto off = [&](std::uint32_t v, int change) { return std::abs(valence[v] + change - 6); };
            if (off(a, -1) + off(b, -1) + off(c, 1) + off(d, 1) >= off(a, 0) + off(b, 0) + off(c, 0) + off(d, 0))
                continue;
            if (length(c, d) > mLongest || !keepsFacing(a, b, c, d)) continue;
            // (a, b, c) and (b, a, d) become (a, d, c) and (b, c, d).
            mMesh.triangles[t1] = {a, d, c};
            mMesh.triangles[t2] = {b, c, d};
            triangleOf.erase(halfEdgeKey(a, b));
            triangleOf.erase(halfEdgeKey(b, a));
            triangleOf[halfEdgeKey(a, d)] = triangleOf[halfEdgeKey(d, c)] = triangleOf[halfEdgeKey(c, a)] = t1;
            triangleOf[halfEdgeKey(b, c)] = triangleOf[halfEdgeKey(c, d)] = triangleOf[halfEdgeKey(d, b)] = t2;
            --valence[a], --valence[b], ++valence[c], ++valence[d];
            touched[t1] = touched[t2] = 1;
            mFrozenNext.insert(key(c, d));
            ++mCounts.flips;
        }
    }

    /// Whether (a, d, c) and (b, c, d) both face within ~84 degrees of the quad's normal.
    bool keepsFacing(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const
    {
        const auto normal = [this](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
            return (mMesh.positions[y] - mMesh.positions[x]).cross(mMesh.positions[z] - mMesh.positions[x]);
        };
        const Vec3d quad = normal(a, b, c) + normal(b, a, d), n1 = normal(a, d, c), n2 = normal(b, c, d);
        return n1.dot(quad) > 0.1 * n1.length() * quad.length() && n2.dot(quad) > 0.1 * n2.length() * quad.length();
    }

    /// The vertex of triangle t that is neither a nor b.
    std::uint32_t opposite(std::uint32_t t, std::uint32_t a, std::uint32_t b) const
    {
        for (const std::uint32_t v : mMesh.triangles[t])
            if (v != a && v != b) return v;
        return a;
    }

    /// Splits edge a -> b of triangle t1 (b -> a of t2) at its midpoint m: (a, b, c) becomes
    /// (a, m, c) and (m, b, c); (b, a, d) becomes (b, m, d) and (m, a, d).
    void split(std::uint32_t a, std::uint32_t b, std::uint32_t t1, std::uint32_t t2)
    {
        const std::uint32_t c = opposite(t1, a, b), d = opposite(t2, a, b);
        const auto m = std::uint32_t(mMesh.positions.size());
        mMesh.positions.push_back(0.5 * (mMesh.positions[a] + mMesh.positions[b]));
        mMesh.ids.push_back(mMesh.nextId++);
        mMesh.triangles[t1] = {a, m, c};
        mMesh.triangles[t2] = {b, m, d};
        mMesh.triangles.push_back({m, b, c});
        mMesh.triangles.push_back({m, a, d});
        mInverted.resize(mMesh.triangles.size(), 0);
        for (const std::uint32_t v : {a, b, c, d}) mFrozenNext.insert(key(m, v));
        ++mCounts.splits;
        mCounts.edits.push_back({MeshEdit::Kind::Split, mMesh.ids[a], mMesh.ids[b], mMesh.ids[m]});
    }

    bool collapsePass()
    {
        if (mMesh.positions.size() <= 4) return false;
        mDeadTriangle.resize(mMesh.triangles.size(), 0);
        std::vector<Edge> candidates;
        for (const Edge& e : edges())
            if (e.length < mShortest && !frozen(e) && change(e) <= kRateTolerance * mE) candidates.push_back(e);
        if (candidates.empty()) return false;
        std::sort(candidates.begin(), candidates.end(), [this](const Edge& x, const Edge& y) {
            return std::make_tuple(x.length, key(x.a, x.b)) < std::make_tuple(y.length, key(y.a, y.b));
        });
        buildStar();
        std::vector<std::uint8_t> touched(mMesh.positions.size(), 0);
        const std::size_t before = mCounts.collapses;
        for (const Edge& e : candidates) {
            if (touched[e.a] || touched[e.b] || !collapse(e.a, e.b)) continue;
            for (const std::uint32_t v : {e.a, e.b})
                for (const std::uint32_t t : star(v))
                    for (const std::uint32_t w : mMesh.triangles[t]) touched[w] = 1;
        }
        return mCounts.collapses > before;
    }

    /// Each vertex's alive triangles.
    void buildStar() { mStars = VertexStars::of(mMesh.triangles, mMesh.positions.size(), &mDeadTriangle); }
    std::vector<std::uint32_t> star(std::uint32_t v) const
    {
        std::vector<std::uint32_t> list;
        for (std::uint32_t i = mStars.start[v]; i < mStars.start[v + 1]; ++i)
            if (!mDeadTriangle[mStars.list[i]]) list.push_back(mStars.list[i]);
        return list;
    }
    std::vector<std::uint32_t> neighbours(std::uint32_t v) const
    {
        std::vector<std::uint32_t> list;
        for (const std::uint32_t t : star(v))
            for (const std::uint32_t w : mMesh.triangles[t])
                if (w != v) list.push_back(w);
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        return list;
    }

    /// Collapses edge (a, b) to its midpoint, keeping the older vertex (the smaller id); false
    /// when a rule refuses it.
    bool collapse(std::uint32_t a, std::uint32_t b)
    {
        const std::vector<std::uint32_t> na = neighbours(a), nb = neighbours(b);
        std::vector<std::uint32_t> common;
        std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
        if (common.size() != 2) return false;  // the link condition: the result stays a 2-manifold
        // Two ends of valence 3 are a tetrahedron, whose collapse passes the vertex test and
        // leaves two triangles back to back.
        if (na.size() == 3 && nb.size() == 3) return false;
        const Vec3d m = 0.5 * (mMesh.positions[a] + mMesh.positions[b]);
        for (const std::uint32_t v : {a, b}) {
            for (const std::uint32_t w : v == a ? na : nb)
                if (w != a && w != b && (mMesh.positions[w] - m).length() > mLongest) return false;
            for (const std::uint32_t t : star(v))
                if (turnsOver(t, a, b, m)) return false;
        }
        const std::uint32_t keep = mMesh.ids[a] < mMesh.ids[b] ? a : b, gone = keep == a ? b : a;
        for (const std::uint32_t t : star(gone)) {
            auto& tri = mMesh.triangles[t];
            if (std::find(tri.begin(), tri.end(), keep) != tri.end()) mDeadTriangle[t] = 1;
            else std::replace(tri.begin(), tri.end(), gone, keep);
        }
        mMesh.positions[keep] = m;
        for (const std::uint32_t w : keep == a ? nb : na)
            if (w != keep) mFrozenNext.insert(key(keep, w));
        for (const std::uint32_t w : keep == a ? na : nb)
            if (w != gone) mFrozenNext.insert(key(keep, w));
        ++mCounts.collapses;
        mCounts.edits.push_back({MeshEdit::Kind::Collapse, mMesh.ids[keep], mMesh.ids[gone], 0});
        return true;
    }

    /// Whether triangle t, not on edge (a, b), faces the other way (or degenerates) once a and b
    /// move to m.
    bool turnsOver(std::uint32_t t, std::uint32_t a, std::uint32_t b, const Vec3d& m) const
    {
        const auto& tri = mMesh.triangles[t];
        const bool hasA = std::find(tri.begin(), tri.end(), a) != tri.end();
        const bool hasB = std::find(tri.begin(), tri.end(), b) != tri.end();
        if (hasA && hasB) return false;  // removed by the collapse
        Vec3d p[3], q[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = mMesh.positions[tri[k]];
            q[k] = tri[k] == a || tri[k] == b ? m : p[k];
        }
        const Vec3d before = (p[1] - p[0]).cross(p[2] - p[0]), after = (q[1] - q[0]).cross(q[2] - q[0]);
        return after.dot(before) <= 0.1 * before.length() * after.length();  // keeps within ~84 degrees
    }

    /// Drops dead triangles, then the vertices they left unused (a collapse's), renumbering the rest in order.
    void compact()
    {
        mDeadTriangle.resize(mMesh.triangles.size(), 0);
        std::size_t kept = 0;
        for (std::size_t t = 0; t < mMesh.triangles.size(); ++t)
            if (!mDeadTriangle[t]) mMesh.triangles[kept++] = mMesh.triangles[t];
        mMesh.triangles.resize(kept);
        mMesh.dropUnusedVertices();
        mDeadTriangle.clear();
    }

    void remember()
    {
        mMemory.lengths.clear();
        for (const Edge& e : edges()) mMemory.lengths[key(e.a, e.b)] = e.length;
        mMemory.frozen = std::move(mFrozenNext);
    }

    TrackedMesh& mMesh;
    EdgeMemory& mMemory;
    std::vector<std::uint8_t> mInverted;
    const double mE, mShortest, mLongest;
    const bool mFlips;
    std::unordered_set<std::uint64_t> mFrozenNext;
    std::vector<std::uint8_t> mDeadTriangle;
    VertexStars mStars;
    RemeshCounts mCounts;
};

}  // namespace

RemeshCounts alterMesh(TrackedMesh& mesh, EdgeMemory& memory, const std::vector<std::uint8_t>& inverted,
                       const RemeshLimits& limits)
{
    return Remesher(mesh, memory, inverted, limits).run();
}

}  // namespace sculpt
