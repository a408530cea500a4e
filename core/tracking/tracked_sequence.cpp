#include "core/tracking/tracked_sequence.h"

namespace sculpt {

TriangleMesh TrackedSegment::frameMesh(std::size_t frame) const
{
    TriangleMesh mesh;
    mesh.positions.assign(positions.at(frame).begin(), positions.at(frame).end());
    mesh.triangles.assign(triangles.begin(), triangles.end());
    return mesh;
}

void TrackedSequence::add(const TrackedMesh& frame)
{
    if (mSegments.empty() || mSegments.back().ids != frame.ids || mSegments.back().triangles != frame.triangles) {
        TrackedSegment segment;
        segment.firstFrame = mFrames;
        segment.triangles = frame.triangles;
        segment.ids = frame.ids;
        mSegments.push_back(std::move(segment));
    }
    std::vector<std::array<float, 3>> points;
    points.reserve(frame.positions.size());
    for (const auto& p : frame.positions) points.push_back({float(p.x()), float(p.y()), float(p.z())});
    mSegments.back().positions.push_back(std::move(points));
    ++mFrames;
}

}  // namespace sculpt
