// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file edge_hold.h
/// @brief Keeps a tracked mesh's edges inside [e, 2e] by sliding their ends along the surface,
///        so ALTERMESH changes connectivity only where the mesh has no room left.
///
/// Relaxed to the triangles' equilibrium, a mesh whose valences are not all 6 spreads its edges
/// over about 1.1 e to 1.8 e: the edges between two valence-7 vertices are the longest, those
/// next to valence 5 the shortest. A motion that stretches one part and shrinks another (a
/// sphere morphing into a box: the corners stretch, the faces shrink) carries those extremes
/// out of [e, 2e] while the triangles around them still have room. Each such edge is brought
/// back within a margin of the limit by sliding its two ends apart or together along their
/// tangent planes (Gauss-Seidel sweeps, as position-based dynamics' distance constraints), which
/// hands the excess to its neighbours; the caller projects the moved vertices between sweeps.
///
/// Only small excursions in well-shaped places are held: an edge that was within 10% of the
/// range at the last step, both of whose ends have only triangles of 20 degrees or more facing
/// along grad phi, and a slide that keeps them so. A part shrinking or growing for good, or a
/// cut's fresh fans, are left to the remesher (holding them folds triangles).

#include "core/tracking/edge_remesher.h"
#include "core/tracking/mesh_adjacency.h"

namespace sculpt {

class EdgeHold {
public:
    /// Edges are held within [(1 + kMargin) e, 2 (1 - kMargin) e].
    static constexpr double kMargin = 0.03;
    /// The sweeps a step makes at most.
    static constexpr int kSweeps = 8;

    /// `normals` (#V, unit grad phi), `fixed` (#V, quasi-critical points: never moved) and the
    /// remesher's `memory` (each edge's length at the last step) are read as they are at each
    /// sweep; which vertices are in well-shaped places is judged once, now.
    EdgeHold(TrackedMesh& mesh, const std::vector<openvdb::Vec3d>& normals, const std::vector<std::uint8_t>& fixed,
             const EdgeMemory& memory, double edge);

    /// One sweep over the edges outside the held range; returns the vertices it moved (off the
    /// surface by the curvature under a slide: project them before the next sweep). Serial, in
    /// triangle order: the same result whatever the thread count.
    std::vector<std::uint32_t> sweep();

private:
    /// Whether every triangle around `v` has its smallest angle at 20 degrees or more and faces
    /// along v's normal, with v at `at`.
    bool wellShapedAround(std::uint32_t v, const openvdb::Vec3d& at) const;
    /// Whether an edge of length `length` (now) is one to hold.
    bool held(std::uint32_t a, std::uint32_t b, double length) const;

    TrackedMesh& mMesh;
    const std::vector<openvdb::Vec3d>& mNormals;
    const std::vector<std::uint8_t>& mFixed;
    const EdgeMemory& mMemory;
    const double mEdge;
    const VertexStars mStars;
    std::vector<std::uint8_t> mWellShaped;  ///< per vertex, as the hold began
};

}  // namespace sculpt
