// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_stats.h
/// @brief Test measures of a field's surface: mean radius, curvature spread.

#include "core/field/field_image.h"

#include <optional>

namespace sculpt::test {

/// Mean and max distance from `centre` of the surface vertices (block mesher).
struct RadiusStats {
    double mean = 0.0, min = 0.0, max = 0.0;
};
RadiusStats surfaceRadius(const FieldImage& field, const openvdb::Vec3d& centre = openvdb::Vec3d(0.0));

/// Variance of the mean curvature (OpenVDB's CurvatureStencil) over voxels within half a voxel of
/// the surface, optionally only those within `radius` of `centre`.
double curvatureVariance(const FieldImage& field, std::optional<std::pair<openvdb::Vec3d, double>> ball = std::nullopt);

}  // namespace sculpt::test
