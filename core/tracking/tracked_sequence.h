#pragma once
/// @file tracked_sequence.h
/// @brief The frames of a tracked mesh, grouped into segments of constant connectivity: within a
///        segment every frame has the same vertices (by id, in the same order) and triangles,
///        which is what a point cache or a set of shape keys can play.

#include "core/mesh/triangle_mesh.h"
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
    /// Appends a frame; a new segment starts when its ids or triangles differ from the last's.
    void add(const TrackedMesh& frame);
    const std::vector<TrackedSegment>& segments() const { return mSegments; }
    int frameCount() const { return mFrames; }

private:
    std::vector<TrackedSegment> mSegments;
    int mFrames = 0;
};

}  // namespace sculpt
