// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file synthetic_scan.h
/// @brief Scans of known shapes for the import tests: a sampled signed distance, and a ball
///        whose radius and centre the imported surface must reproduce.

#include "core/field/field_image.h"
#include "core/scan/scan_volume.h"

#include <openvdb/openvdb.h>
#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <functional>
#include <string>
#include <utility>

namespace sculpt::test {

/// A shape given by its signed distance (world units, negative inside) sampled 0 outside .. 200
/// inside with a linear ramp across the surface (100 on it), on a lattice with the given spacing
/// and origin (16-bit samples).
vtkSmartPointer<vtkImageData> sampledImage(const openvdb::Coord& dims, const openvdb::Vec3d& spacing,
                                           const openvdb::Vec3d& origin,
                                           const std::function<double(const openvdb::Vec3d&)>& sdf);

/// The sample sampledImage() gives at signed distance d.
double rampSample(double d);

/// Radius and centre of the level set's surface, from its mesh's vertices.
std::pair<double, openvdb::Vec3d> sphereOf(const FieldImage& field);

struct SyntheticBall {
    openvdb::Coord dims{40, 40, 22};
    openvdb::Vec3d spacing{1.0, 1.0, 2.0};
    openvdb::Vec3d origin{-13.0, 7.0, 31.0};
    openvdb::Vec3d centre = origin + openvdb::Vec3d(19.5, 21.0, 20.0);
    double radius = 12.0;
    double distance(const openvdb::Vec3d& p) const { return (p - centre).length() - radius; }
    vtkSmartPointer<vtkImageData> image() const;
};

/// Imports the scan at iso 100 and its finest spacing, and expects the ball's radius and centre
/// within half a voxel; `format` names the case in failures.
void expectBallAt(const ScanVolume& scan, const SyntheticBall& ball, const std::string& format);

/// A raw label map (48 x 32 x 32 bytes) of three labels: a box (1) around a ball (2), and a
/// ball (3) beside them.
void writeThreeLabelRaw(const std::filesystem::path& file);

}  // namespace sculpt::test
