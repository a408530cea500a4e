// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_tracker.h
/// @brief A triangle mesh that moves with a changing level set instead of being re-meshed
///        (Nesme and Bouthors, dynamic triangulation of implicit surfaces).
///
/// Seeded from the welded marching-cubes mesh and relaxed on the field, it then follows the
/// field step by step: each step moves the vertices by any known displacement, projects them
/// back onto phi = 0 (surface_projection.h), unfolds inverted triangles, slides the vertices
/// along the surface towards equilateral triangles (corotated_triangles.h), slides edges leaving
/// [e, 2e] back where the triangles around them have room (edge_hold.h), changes the others
/// locally (edge_remesher.h) and slides and projects again. Where the surface's topology
/// changes the mesh is cut and closed there (topology_surgery.h) or seeded again. Vertices keep their ids while they
/// exist; connectivity changes only where an edge leaves its range, so a sequence that only
/// moves keeps its vertex count and triangles. Call step() after every evolution step, not only
/// at frames: between two steps the surface moves less than the band, so projection finds it.

#include "core/field/field_image.h"
#include "core/tracking/corotated_triangles.h"
#include "core/tracking/edge_remesher.h"
#include "core/tracking/mesh_edit.h"
#include "core/tracking/surface_projection.h"
#include "core/tracking/topology_surgery.h"

#include <functional>

namespace sculpt {

struct TrackerOptions {
    double edgeVoxels = 1.5;  ///< e, the target edge length, in voxels
    /// The triangles' stiffness times the step (E dt), and the conjugate-gradient steps per
    /// relaxation: near the springs' equilibrium, so a morph's uneven stretch spreads over the
    /// whole surface instead of splitting the edges where it lands (sphere -> box, radii 10 to
    /// 13: 24 edge changes against 35 at gain 1 with 6 steps; gain 10 with 20 steps gives 16 at
    /// twice the relaxation's cost).
    double gain = 3.0;
    int conjugateGradientSteps = 10;
    /// The same for the steps that settle a cut and closed mesh (topology_surgery.h).
    double settleGain = 1.0;
    int settleConjugateGradientSteps = 6;
    /// The rest triangle's side, in e: the side the seeded mesh lives at, so no triangle starts
    /// under stress (a compressed one buckles).
    double restEdges = 1.4;
    int seedSteps = 40;  ///< steps on the seeding field before the mesh is first used
    /// Seeding keeps edges within [seedShortestEdges, seedLongestEdges] e (later steps: [e, 2e]):
    /// the seed's edges, relaxed, spread over 1.04 to 1.8 e on a sphere (its valences are not
    /// all 6), so a narrower seeding band leaves room to stretch and to shrink (sphere -> box: 24
    /// edge changes against 171 with the band [1.41, 2]; a grab stroke: none against 8).
    double seedShortestEdges = 1.35;
    double seedLongestEdges = 1.85;
};

/// A point left where it was because projection found no surface to follow.
struct QuasiCriticalPoint {
    std::uint32_t vertexId = 0;
    std::uint32_t triangle = 0;  ///< one of its triangles, at the step it was found
    openvdb::Vec3d position{0.0};
};

/// What one step did.
struct TrackingStep {
    std::size_t splits = 0, collapses = 0;
    std::vector<MeshEdit> edits;  ///< the splits and collapses, in order
    std::size_t inverted = 0;     ///< triangles facing against grad phi when the step began
    std::vector<QuasiCriticalPoint> quasiCritical;
    /// The surface's topology changed and the mesh was cut and closed there (stage 2): the
    /// vertices away from the event keep their ids; connectivity changed, a new segment begins.
    Surgery surgery;
    /// The surface's topology changed where surgery could not follow: the mesh was seeded again
    /// from the marching-cubes mesh (new vertex ids, stage 1), a new segment begins.
    bool reseeded = false;
    /// Shells that shrank under MeshTracker::kResolvableEdges e across, dropped with their
    /// vertices (the rest keep their ids); a new segment begins.
    std::size_t vanishedShells = 0;
    /// Over MeshTracker::kLostFoldedShare of the triangles were inverted: the mesh had lost the
    /// surface and was seeded again (reseeded is set too), whatever the topology.
    bool folded = false;
};

class MeshTracker {
public:
    /// Steps on the same field after a surgery, before the step returns.
    static constexpr int kSettleSteps = 4;
    /// Shells under this many e across on every side are below the mesh's resolution: a closed
    /// mesh with edges of at least e holds only a handful of triangles there. The marching-cubes
    /// specks that parts thinner than a voxel leave as they move (one voxel across, eight
    /// triangles, appearing and vanishing from step to step) are neither seeded nor counted in
    /// the ground truth, and a tracked shell under it is dropped once the truth has lost it.
    static constexpr double kResolvableEdges = 2.0;
    /// A mesh folded over more than this share of its triangles is seeded again: past it, folds
    /// feed themselves (unfolding and remeshing there fold more); below it they are unfolded
    /// locally. (The measurement that set it: the log of commit bf01850.)
    static constexpr double kLostFoldedShare = 0.01;

    /// Seeds from `field`'s welded marching-cubes mesh (its resolvable shells), relaxed
    /// options.seedSteps steps on it.
    explicit MeshTracker(const FieldImage& field, const TrackerOptions& options = {});

    /// One step on `field` as it is now. `displacement`, where given, moves each vertex first
    /// (a known velocity times the step: a rigid move, a grab). Then the Euler characteristic and
    /// shell count of the marching-cubes mesh's resolvable shells, the ground truth, are compared
    /// with the tracked mesh's, and a mesh that folded over kLostFoldedShare of its triangles is
    /// seeded again: when they differ, tracked shells under the resolution are dropped
    /// first (a part shrunk away), then, if they still differ, the mesh is cut and closed where
    /// they do (topology_surgery.h, then settled kSettleSteps steps), or, where that fails, seeded
    /// again. Quasi-critical points alone change nothing: they stay where they were until the
    /// field shows them a surface again or a topology event cuts them away. Deterministic: the
    /// same mesh whatever the thread count.
    /// Cost: the projections and the relaxation are O(vertices); the check meshes the field.
    TrackingStep step(const FieldImage& field,
                      const std::function<openvdb::Vec3d(const openvdb::Vec3d&)>& displacement = {});

    const TrackedMesh& mesh() const { return mMesh; }
    /// e in world units.
    double edgeLength() const { return mEdge; }

private:
    /// The welded marching-cubes mesh of `field` without the shells under kResolvableEdges e,
    /// ids from 0: the ground truth of the topology and what a seed starts from.
    TrackedMesh resolvableSurface(const FieldImage& field) const;
    /// Seeds from `surface` (resolvableSurface of `field`; its ids moved after every id used)
    /// and relaxes it.
    void seed(const FieldImage& field, const TrackedMesh& surface);
    /// Stage 1: seeds from `surface` (as seed()) and says so in `report`.
    TrackingStep reseed(const FieldImage& field, const TrackedMesh& surface, TrackingStep report);
    /// The step without the topology check; `holding`: edges leaving [e, 2e] are slid back
    /// where there is room (edge_hold.h) before the remesher sees them (not while seeding, whose
    /// band is another, nor while a cut settles).
    TrackingStep advance(const FieldImage& field, const std::function<openvdb::Vec3d(const openvdb::Vec3d&)>& move,
                         const RemeshLimits& limits, const RelaxOptions& relaxation, bool holding);
    /// The triangles at rest at restEdges e, relaxed with this gain and these steps.
    RelaxOptions relaxation(double gain, int conjugateGradientSteps) const;
    /// One quasi-static step of the triangles along the surface, then back onto it.
    void relax(const FieldImage& field, const RelaxOptions& options);
    /// Projects every vertex (each judged afresh: a quasi-critical one stays where it is),
    /// keeping grad phi's direction per vertex.
    void project(const FieldImage& field);
    void projectVertex(const FieldProbe& probe, std::size_t v);
    /// Sweeps of EdgeHold, the moved vertices projected after each.
    void holdEdges(const FieldImage& field);
    std::vector<std::uint8_t> invertedTriangles() const;
    /// Moves the vertex of each inverted triangle nearest its opposite edge across that edge.
    void unfold(const std::vector<std::uint8_t>& inverted);
    std::vector<QuasiCriticalPoint> flagged() const;

    TrackerOptions mOptions;
    double mEdge;
    TrackedMesh mMesh;
    EdgeMemory mMemory;
    std::vector<openvdb::Vec3d> mNormals;
    std::vector<std::uint8_t> mQuasiCritical;
};

}  // namespace sculpt
