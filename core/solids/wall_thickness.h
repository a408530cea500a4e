// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file wall_thickness.h
/// @brief How thick the solid is under a surface point, and how far a surface overhangs: what a
///        print needs checked (Blender's Mesh Analysis does it on the mesh, with a ray cast).
///
/// Thickness is measured on the field itself, no mesh and no BVH: from a point on the surface
/// along -grad phi (into the solid) to the next zero crossing, by sphere tracing (each step the
/// |phi| there, which never passes a surface; where the band knows only the sign, a band's width).
/// Overhang is the angle between the outward normal and straight down (the print direction's
/// opposite): 0 for a surface facing the build plate, 90 for a wall; only downward faces overhang.

#include "core/field/field_image.h"

#include <openvdb/openvdb.h>

#include <optional>

namespace sculpt {

/// The solid's thickness under `surfacePoint` (world units), along -normal, or nothing if no far
/// wall comes within `farthestWorld`. `normal`: the outward unit normal there.
std::optional<double> wallThicknessAt(const openvdb::FloatGrid& grid, const openvdb::Vec3d& surfacePoint,
                                      const openvdb::Vec3d& normal, double farthestWorld);

/// Degrees a surface of outward unit normal `normal` overhangs for a print along `up`: 90 minus
/// its angle below the horizontal, 0 facing straight down; nothing for a face looking up or
/// sideways (normal . up >= 0).
std::optional<double> overhangDegrees(const openvdb::Vec3d& normal, const openvdb::Vec3d& up);

struct ThinnestWall {
    double thickness = 0.0;     ///< world units
    openvdb::Vec3d where{0.0};  ///< the surface point
    std::size_t samples = 0;    ///< surface points measured
};

/// The thinnest wall of the field: measured at the closest surface point of every band voxel
/// within half a voxel of the surface, in parallel; none if none is thinner than `farthestWorld`.
std::optional<ThinnestWall> thinnestWall(const FieldImage& field, double farthestWorld);

}  // namespace sculpt
