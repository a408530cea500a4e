// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file edge_remesher.h
/// @brief ALTERMESH (Nesme and Bouthors): the local changes that keep a tracked mesh's edges
///        between e and 2e while the surface stretches and shrinks.
///
/// With e the target edge length: an edge longer than 2e is split at its midpoint unless it
/// shrank by more than 0.1 e since the last step (it is already on its way back); an edge
/// shorter than e is collapsed to its midpoint unless it grew by more than 0.1 e. (The paper's
/// text swaps the two rules; its figure is the one followed here.) An edge a change made is
/// frozen for the next step, so a split and a collapse never chase each other. A collapse is
/// refused when it would make the mesh non-manifold (the two ends share neighbours other than
/// the two opposite vertices, or the shell is a tetrahedron), turn a triangle over, or make an
/// edge longer than the split length (2e); an edge of an inverted triangle is never split.
/// Changes are made in passes over independent edges (no two touching the same triangle), the
/// longest split and the shortest collapsed first.
/// Seeding also flips edges towards valence 6 (never while tracking: a flip changes connectivity).

#include "core/tracking/mesh_adjacency.h"
#include "core/tracking/mesh_edit.h"
#include "core/tracking/tracked_mesh.h"

#include <unordered_map>
#include <unordered_set>

namespace sculpt {

/// What ALTERMESH remembers between steps, keyed by edgeKey of vertex ids.
struct EdgeMemory {
    std::unordered_map<std::uint64_t, double> lengths;  ///< each edge's length at the last step
    std::unordered_set<std::uint64_t> frozen;           ///< edges changed at the last step
};

struct RemeshCounts {
    std::size_t splits = 0, collapses = 0, flips = 0;
    std::vector<MeshEdit> edits;  ///< the splits and collapses, in order (flips are not listed)
};

/// How a pass treats the mesh: tracking keeps connectivity unless an edge leaves [e, 2e];
/// seeding, which gives new ids anyway, shapes a mesh with room to move.
struct RemeshLimits {
    double edge = 1.0;      ///< e, world units
    double shortest = 0.0;  ///< edges under this are collapsed (e when 0)
    double longest = 0.0;   ///< edges over this are split (2e when 0)
    /// Flip edges where that brings the four vertices' valences nearer 6: a regular mesh relaxes
    /// to nearly equal edges, so it can stretch and shrink further before an edge leaves [e, 2e].
    bool flips = false;
};

/// One ALTERMESH pass over `mesh` (closed, 2-manifold). `inverted` marks triangles (#F) whose
/// normal opposes grad phi. New vertices lie on edge midpoints, off the surface: project them
/// after. Updates `memory` for the next step.
RemeshCounts alterMesh(TrackedMesh& mesh, EdgeMemory& memory, const std::vector<std::uint8_t>& inverted,
                       const RemeshLimits& limits);

}  // namespace sculpt
