// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file cross_section.h
/// @brief Where a plane cuts the solid, from the field itself (not from a mesh): the region of
///        the plane inside the surface as triangles (a clip plane's cap), its outline (a slice's
///        contour) and its area.
///
/// The plane is sampled on a square lattice of the field's voxel size spanning the field's
/// leaves; each lattice cell is split into two triangles over which phi is linear, and the part
/// of each where phi < 0 is kept (a triangle or a quad): neighbouring cells interpolate their
/// shared edges alike, so the region has no gaps (and no T-junctions, which would show as
/// pixel cracks in a drawn cap), and its error is second order in the voxel size.

#include "core/field/field_image.h"
#include "core/mesh/triangle_mesh.h"

#include <openvdb/openvdb.h>

#include <array>
#include <vector>

namespace sculpt {

/// A plane: the points p with dot(p - origin, normal) = 0; `normal` unit.
struct SectionPlane {
    openvdb::Vec3d origin{0.0};
    openvdb::Vec3d normal{0.0, 0.0, 1.0};
};

struct CrossSection {
    TriangleMesh region;                                 ///< the inside of the cut, its normals `normal`
    std::vector<std::array<openvdb::Vec3d, 2>> outline;  ///< segments of phi = 0 on the plane
    double area = 0.0;                                   ///< of `region`
};

/// What crossSection makes: the region too (a cap), or the outline alone (a slice's contour).
enum class SectionParts { RegionAndOutline, Outline };

/// The cut of `field` by `plane` (both in the field's world); with SectionParts::Outline the
/// region is left empty (and its area 0).
CrossSection crossSection(const FieldImage& field, const SectionPlane& plane,
                          SectionParts parts = SectionParts::RegionAndOutline);

/// The cut of a placed field (a piece: world from its field's world, row vectors) by a plane of
/// the world, in the world: its region's normals the plane's, its area the world's.
CrossSection placedCrossSection(const FieldImage& field, const openvdb::Mat4d& placement, const SectionPlane& plane,
                                SectionParts parts = SectionParts::RegionAndOutline);

}  // namespace sculpt
