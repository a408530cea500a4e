// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file corotated_triangles.h
/// @brief The tangential relaxation of a tracked mesh: co-rotational constant-strain triangles
///        that all rest as one equilateral triangle of side e, solved quasi-statically
///        (Nesme and Bouthors, dynamic triangulation of implicit surfaces).
///
/// Each triangle j pulls its vertices towards the rest shape turned onto it:
/// f_j = R_j K (R_j^T x - x0), R_j the rotation of its deformation gradient (re-extracted every
/// step), K linear elasticity (Poisson's ratio 0.3). One implicit step
/// (I - dt df/dx) dx = dt f, with df/dx the stiffness turned by the R_j, is solved by a
/// conjugate gradient whose vectors are filtered onto each vertex's tangent plane (Baraff and
/// Witkin's constraint filter): the relaxation only slides vertices along the surface, the
/// projection keeps them on it. The stiffness enters only as the gain E dt: a large gain is
/// the equilibrium of the springs, a small one a fraction of the way there.

#include <openvdb/Types.h>

#include <array>
#include <cstdint>
#include <vector>

namespace sculpt {

struct RelaxOptions {
    double restEdge = 1.0;           ///< e, world units: the rest triangle's side
    double gain = 1.0;               ///< E dt, per unit of the rest area's stiffness
    int conjugateGradientSteps = 6;  ///< 2 to 10 in the paper
};

/// The displacement of each vertex (world units) that one quasi-static step of the triangles'
/// elastic forces asks, within the tangent plane of its unit normal `normals[v]`; vertices with
/// `fixed[v]` set do not move (quasi-critical points).
/// @param positions #V world points; @param triangles #F index triples, counter-clockwise from
/// outside. Serial, so the same result whatever the thread count. Cost O(F) per CG step.
std::vector<openvdb::Vec3d> relaxationStep(const std::vector<openvdb::Vec3d>& positions,
                                           const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                           const std::vector<openvdb::Vec3d>& normals,
                                           const std::vector<std::uint8_t>& fixed, const RelaxOptions& options);

}  // namespace sculpt
