// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file morph_tracking.h
/// @brief A morph's tracked mesh (`sculpt morph --tracked`, the Morph panel's "tracked mesh"):
///        seeded on the first frame, stepped after every evolution step (frames are farther
///        apart than the band), kept at every frame with its quality.

#include "core/tracking/mesh_tracker.h"
#include "core/tracking/tracked_mesh_quality.h"
#include "core/tracking/tracked_sequence.h"

#include <optional>

namespace sculpt {

/// What the tracked mesh went through over a whole morph.
struct TrackingTally {
    std::size_t steps = 0, splits = 0, collapses = 0, inverted = 0, quasiCritical = 0;
    std::size_t surgeries = 0, reseeds = 0;  ///< topology events cut and closed (stage 2), seeded again (stage 1)
    std::size_t vanished = 0;                ///< shells shrunk under the tracked mesh's resolution, dropped
    std::size_t folds = 0;                   ///< of the reseeds, those of a mesh that had folded (not topology)
    void add(const TrackingStep& s);
};

/// A frame of the tracked mesh: its quality, and the points flagged quasi-critical since the last frame.
struct TrackedFrame {
    TrackedMeshQuality quality;
    std::size_t flagged = 0;
    std::size_t segment = 0;
};

class MorphTracking {
public:
    /// At each frame of the morph (the first seeds the mesh).
    void frame(const FieldImage& field);
    /// After each evolution step.
    void step(const FieldImage& field);

    const TrackedSequence& sequence() const { return mSequence; }
    const std::vector<TrackedFrame>& frames() const { return mFrames; }
    const TrackingTally& tally() const { return mTally; }
    /// e, world units (0 before the first frame).
    double edgeLength() const { return mTracker ? mTracker->edgeLength() : 0.0; }

    /// Frame `index`'s mesh: its segment's triangles and that frame's positions.
    TriangleMesh frameMesh(int index) const;

private:
    std::optional<MeshTracker> mTracker;
    TrackedSequence mSequence;
    std::vector<TrackedFrame> mFrames;
    TrackingTally mTally;
    std::size_t mFlaggedSinceFrame = 0;
    std::vector<MeshEdit> mEditsSinceFrame;  ///< what the sequence replays to keep the segment going
};

}  // namespace sculpt
