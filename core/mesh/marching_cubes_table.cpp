// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/marching_cubes_table.h"

#include <stdexcept>
#include <vector>

namespace sculpt::mc {

namespace {

constexpr std::array<int, 12> kEdgeCorner = {0, 2, 4, 6, 0, 1, 4, 5, 0, 1, 2, 3};

using Point = std::array<double, 3>;

Point cornerPoint(int c) { return {double(c & 1), double(c >> 1 & 1), double(c >> 2 & 1)}; }

Point edgeMidpoint(int e)
{
    Point p = cornerPoint(kEdgeCorner[e]);
    p[edgeAxis(e)] = 0.5;
    return p;
}

int edgeBetween(int c1, int c2)
{
    const int lower = c1 < c2 ? c1 : c2;
    const int axis = (c1 ^ c2) == 1 ? 0 : (c1 ^ c2) == 2 ? 1 : 2;
    for (int e = axis * 4; e < axis * 4 + 4; ++e) {
        if (kEdgeCorner[e] == lower) return e;
    }
    throw std::logic_error("corners do not share an edge");
}

std::array<Face, 6> makeFaces()
{
    std::array<Face, 6> faces{};
    for (int axis = 0; axis < 3; ++axis) {
        const int u = 1 << (axis + 1) % 3, v = 1 << (axis + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            const int base = side << axis;
            faces[axis * 2 + side] = {axis, side, {base, base | u, base | u | v, base | v}};
        }
    }
    return faces;
}

const std::array<Face, 6> kFaces = makeFaces();

struct Segment {
    int from, to;  // edges, directed so that the outside lies to the right seen from outside
};

/// Directs the segment between edges a and b on face f, given a corner known to be inside or
/// outside: (outward face normal x direction) must point away from the inside.
Segment orientedSegment(int a, int b, const Face& f, int refCorner, bool refInside)
{
    Point n{0.0, 0.0, 0.0};
    n[f.axis] = f.side ? 1.0 : -1.0;
    const Point pa = edgeMidpoint(a), pb = edgeMidpoint(b), ref = cornerPoint(refCorner);
    const Point d{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    const Point side{n[1] * d[2] - n[2] * d[1], n[2] * d[0] - n[0] * d[2], n[0] * d[1] - n[1] * d[0]};
    const double s = side[0] * (ref[0] - pa[0]) + side[1] * (ref[1] - pa[1]) + side[2] * (ref[2] - pa[2]);
    return (s < 0.0) == refInside ? Segment{a, b} : Segment{b, a};
}

/// Iso-curve segments of one face: none, one, or two on an ambiguous face.
void faceSegments(unsigned cube, const Face& f, bool insideJoin, std::vector<Segment>& out)
{
    bool in[4];
    int crossings = 0;
    for (int i = 0; i < 4; ++i) in[i] = (cube >> f.corners[i] & 1) != 0;
    for (int i = 0; i < 4; ++i) crossings += in[i] != in[(i + 1) % 4];
    auto edgeAfter = [&](int i) { return edgeBetween(f.corners[i], f.corners[(i + 1) % 4]); };
    if (crossings == 2) {
        int first = -1, second = -1;
        for (int i = 0; i < 4; ++i) {
            if (in[i] == in[(i + 1) % 4]) continue;
            (first < 0 ? first : second) = edgeAfter(i);
        }
        const int ref = in[0] ? 0 : in[1] ? 1 : in[2] ? 2 : 3;
        out.push_back(orientedSegment(first, second, f, f.corners[ref], true));
    } else if (crossings == 4) {
        // Cut off each corner that is not joined to its diagonal partner.
        for (int i = 0; i < 4; ++i) {
            if (in[i] == insideJoin) continue;
            out.push_back(orientedSegment(edgeAfter((i + 3) % 4), edgeAfter(i), f, f.corners[i], in[i]));
        }
    }
}

bool edgeOnFace(int e, const Face& f)
{
    const int lower = kEdgeCorner[e], upper = lower | 1 << edgeAxis(e);
    return (lower >> f.axis & 1) == f.side && (upper >> f.axis & 1) == f.side;
}

/// A diagonal joining two vertices of one cube face lies in that face, where the neighbouring
/// cell could draw it too (the edge would then have four triangles). Only the cell on the face's
/// low side (the face is its high face, side 1) may draw it.
bool diagonalAllowed(int a, int b)
{
    for (const Face& f : kFaces) {
        if (f.side == 0 && edgeOnFace(a, f) && edgeOnFace(b, f)) return false;
    }
    return true;
}

using Triangle = std::array<std::uint8_t, 3>;

/// Triangulates a loop of edge vertices (polygon triangulation by intervals), using only allowed
/// diagonals; among valid choices the lowest apex, so a convex fan when it is allowed. Empty if
/// no such triangulation exists.
std::vector<Triangle> triangulateLoop(const std::vector<int>& loop)
{
    const int n = int(loop.size());
    // ok[i][j]: the sub-polygon i..j (closed by i-j) can be triangulated; apex[i][j] chosen.
    std::vector<std::vector<int>> apex(size_t(n), std::vector<int>(size_t(n), -1));
    for (int len = 2; len < n; ++len) {
        for (int i = 0; i + len < n; ++i) {
            const int j = i + len;
            for (int k = i + 1; k < j && apex[size_t(i)][size_t(j)] < 0; ++k) {
                const bool left = k == i + 1 || (apex[size_t(i)][size_t(k)] >= 0 &&
                                                 diagonalAllowed(loop[size_t(i)], loop[size_t(k)]));
                const bool right = k == j - 1 || (apex[size_t(k)][size_t(j)] >= 0 &&
                                                  diagonalAllowed(loop[size_t(k)], loop[size_t(j)]));
                if (left && right) apex[size_t(i)][size_t(j)] = k;
            }
        }
    }
    if (apex[0][size_t(n - 1)] < 0) return {};
    std::vector<Triangle> out;
    std::vector<std::pair<int, int>> pending{{0, n - 1}};
    while (!pending.empty()) {
        const auto [i, j] = pending.back();
        pending.pop_back();
        if (j - i < 2) continue;
        const int k = apex[size_t(i)][size_t(j)];
        out.push_back({std::uint8_t(loop[size_t(i)]), std::uint8_t(loop[size_t(k)]), std::uint8_t(loop[size_t(j)])});
        pending.push_back({i, k});
        pending.push_back({k, j});
    }
    return out;
}

/// Fan around a vertex at the loop's centre: no diagonal at all, so always manifold.
std::vector<Triangle> fanAroundCentre(const std::vector<int>& loop, Triangulation& t)
{
    if (t.centreLoopSize != 0) throw std::logic_error("marching cubes: two loops need a centre");
    std::vector<Triangle> out;
    for (size_t i = 0; i < loop.size(); ++i) {
        t.centreLoop[t.centreLoopSize++] = std::uint8_t(loop[i]);
        out.push_back({std::uint8_t(kCentre), std::uint8_t(loop[i]), std::uint8_t(loop[(i + 1) % loop.size()])});
    }
    return out;
}

Triangulation triangulate(unsigned cube, const Case& info, unsigned bits)
{
    std::vector<Segment> segments;
    int ambiguous = 0;
    for (int f = 0; f < 6; ++f) {
        const bool isAmbiguous = ambiguous < info.ambiguousFaceCount && info.ambiguousFaces[ambiguous] == f;
        const bool join = isAmbiguous && (bits >> ambiguous++ & 1);
        faceSegments(cube, kFaces[f], join, segments);
    }
    std::array<int, 12> next;
    next.fill(-1);
    for (const Segment& s : segments) {
        if (next[s.from] >= 0) throw std::logic_error("marching cubes: edge leaves twice");
        next[s.from] = s.to;
    }
    Triangulation t;
    std::array<bool, 12> visited{};
    for (int start = 0; start < 12; ++start) {
        if (next[start] < 0 || visited[start]) continue;
        std::vector<int> loop;
        for (int e = start; !visited[e]; e = next[e]) {
            if (e < 0) throw std::logic_error("marching cubes: open loop");
            visited[e] = true;
            loop.push_back(e);
        }
        auto triangles = triangulateLoop(loop);
        if (triangles.empty()) triangles = fanAroundCentre(loop, t);
        for (const auto& tri : triangles) t.edges[t.triangleCount++] = tri;
    }
    return t;
}

bool isAmbiguous(unsigned cube, const Face& f)
{
    const bool a = cube >> f.corners[0] & 1, b = cube >> f.corners[1] & 1;
    const bool c = cube >> f.corners[2] & 1, d = cube >> f.corners[3] & 1;
    return a == c && b == d && a != b;
}

struct Table {
    std::array<Case, 256> cases;
    std::vector<Triangulation> entries;

    Table()
    {
        for (unsigned cube = 0; cube < 256; ++cube) {
            Case& info = cases[cube];
            for (int f = 0; f < 6; ++f) {
                if (isAmbiguous(cube, kFaces[f])) info.ambiguousFaces[info.ambiguousFaceCount++] = std::uint8_t(f);
            }
            info.firstEntry = std::uint32_t(entries.size());
            for (unsigned bits = 0; bits < (1u << info.ambiguousFaceCount); ++bits) {
                entries.push_back(triangulate(cube, info, bits));
                info.mayUseCentre = info.mayUseCentre || entries.back().centreLoopSize > 0;
            }
        }
    }
};

const Table& table()
{
    static const Table instance;
    return instance;
}

}  // namespace

int edgeCorner(int e) { return kEdgeCorner[e]; }

const Face& face(int f) { return kFaces[f]; }

const Triangulation& Case::triangulation(unsigned bits) const { return table().entries[firstEntry + bits]; }

const Case& cubeCase(unsigned cubeIndex) { return table().cases[cubeIndex]; }

}  // namespace sculpt::mc
