// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file tracked_sequence.h
/// @brief The frames of a tracked mesh, grouped into segments of constant connectivity: within a
///        segment every frame has the same vertices (by id, in the same order) and triangles,
///        which is what a point cache or a set of shape keys can play.
///
/// The tracker changes connectivity locally (edge_remesher.h): a split adds a vertex at an edge's
/// midpoint, a collapse merges two vertices. Both are kept inside one segment the way Hoppe's
/// geomorphs keep a progressive mesh's: a vertex a split makes is in the segment's frames before
/// it too, at the midpoint of its edge there (its four triangles lie flat in the two they split),
/// and a vertex a collapse removes stays, on the vertex it was merged into (its two triangles on
/// the edge lie flat, of no area). So every frame of a segment is exactly the tracked surface of
/// that frame, and a morph that only grows and shrinks plays as one segment. A segment ends where
/// the replayed edits do not give the frame's triangles (a topology event cut and closed the mesh
/// or seeded it again), or where merged vertices would pass kMostMerged of its vertices (the
/// surface shrank: a new segment drops them). Where collapses had merged edges into the one a
/// split cuts, each of those edges is cut, by the new vertex or by a vertex riding on it that
/// only the segment has (its id counts down from kFirstExportOnlyId, far above the tracker's).

#include "core/mesh/triangle_mesh.h"
#include "core/tracking/mesh_edit.h"
#include "core/tracking/tracked_mesh.h"

#include <array>
#include <vector>

namespace sculpt {

struct TrackedSegment {
    int firstFrame = 0;                                        ///< index of its first frame in the sequence
    std::vector<std::array<std::uint32_t, 3>> triangles;       ///< #F, shared by its frames
    std::vector<std::uint32_t> ids;                            ///< #V stable vertex ids
    std::vector<std::vector<std::array<float, 3>>> positions;  ///< per frame, #V world points

    /// Its `frame`-th frame (counted from firstFrame) as a mesh.
    TriangleMesh frameMesh(std::size_t frame) const;
};

class TrackedSequence {
public:
    /// The largest share of a segment's vertices that may ride on others after collapses.
    static constexpr double kMostMerged = 0.1;
    /// The ids of vertices only a segment has count down from here: far above the tracker's, and
    /// within a signed 32-bit int (USD's primvar of ids).
    static constexpr std::uint32_t kFirstExportOnlyId = 0x7fffffffu;

    /// Appends a frame, reached from the last one by `edits` (the tracker's splits and collapses
    /// since, in order); it joins the last segment when they replay onto it (see above).
    void add(const TrackedMesh& frame, const std::vector<MeshEdit>& edits = {});
    const std::vector<TrackedSegment>& segments() const { return mSegments; }
    int frameCount() const { return mFrames; }

private:
    void start(const TrackedMesh& frame);
    /// Replays `edits` on the last segment and appends `frame` to it; false (the segment
    /// untouched) when the result is not the frame's mesh.
    bool extend(const TrackedMesh& frame, const std::vector<MeshEdit>& edits);

    std::vector<TrackedSegment> mSegments;
    /// Per vertex of the last segment: the vertex whose position it takes (itself unless merged).
    std::vector<std::uint32_t> mKeeper;
    std::uint32_t mNextExportOnlyId = kFirstExportOnlyId;
    int mFrames = 0;
};

}  // namespace sculpt
