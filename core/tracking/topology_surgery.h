// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file topology_surgery.h
/// @brief A topology event's second stage (Nesme and Bouthors, dynamic triangulation of implicit
///        surfaces): the tracked mesh is cut and closed only where the surface's topology changed,
///        so the vertices away from the event keep their ids.
///
/// Where the topology changed, the mesh contradicts the field, and these mark the event:
/// - two sheets facing each other across what the mesh calls outside, now joined by solid
///   (phi < 0 midway: shells merging, a hole closing), or back to back across what it calls
///   solid, now parted by air (phi > 0 midway: a neck pinching off, a hole opening): vertex pairs
///   within 3 voxels, normals opposed;
/// - one piece of surface covered by two sheets (vertices under a voxel apart, normals alike, not
///   neighbours): projection brought both onto a neck;
/// - triangles whose centroid is over 0.75 voxel off the surface (spanning a gap), and points
///   left quasi-critical.
/// The triangles on those vertices are cut away (more where two borders would touch, so every
/// border loop is simple). When the Euler characteristic falls (merges, holes opening) the loops
/// are bridged in pairs, nearest centroids first (several holes can open in one step), by a
/// strip choosing the shorter diagonal at each step; when it rises (pinches, holes closing) each
/// loop is capped by a fan around a new vertex at its centroid. The result must be a closed,
/// oriented 2-manifold of the marching-cubes mesh's topology. Where it is not (the marks held
/// arcs of a neck, not the ring round it), triangles nearer the surface are marked too (centroids
/// over 0.5, then 0.3 voxel off), then the cut is widened by up to two rings of vertices; if none
/// of these works the mesh is left as it was (the caller then seeds it again: stage 1). New vertices lie off the surface and new edges may be
/// long: project, relax and remesh after.

#include "core/field/field_image.h"
#include "core/mesh/surface_topology.h"
#include "core/tracking/tracked_mesh.h"

namespace sculpt {

enum class SurgeryKind {
    None,    ///< not applied: the mesh is unchanged
    Bridge,  ///< two loops joined by a strip (shells merged, a hole opened)
    Cap,     ///< two loops closed by fans (a neck pinched off, a hole closed)
};

struct Surgery {
    SurgeryKind kind = SurgeryKind::None;
    openvdb::Vec3d centre{0.0};  ///< the mean of the contradicted vertices, world units
    double radius = 0.0;         ///< the farthest removed vertex from the centre, world units
    std::size_t loops = 0;       ///< border loops cut (two per merge, pinch or hole)
    std::size_t removedVertices = 0, addedVertices = 0;
};

/// Gives `mesh` (closed, 2-manifold) the topology `truth` of `field`'s zero level set by the
/// local surgery above, if it can. `normals[v]` is the unit grad phi at vertex v.
/// Cost: O(V) for the pair search (a spatial hash), O(event) for the surgery.
Surgery operateOnTopology(TrackedMesh& mesh, const std::vector<openvdb::Vec3d>& normals,
                          const std::vector<std::uint8_t>& quasiCritical, const FieldImage& field,
                          const SurfaceTopology& truth);

/// Whether every directed edge of `triangles` appears once and its reverse once: a closed,
/// oriented 2-manifold (no border, no edge shared by three triangles).
bool closedOrientedManifold(const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace sculpt
