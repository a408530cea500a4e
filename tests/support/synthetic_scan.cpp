// SPDX-License-Identifier: Apache-2.0
#include "tests/support/synthetic_scan.h"

#include "core/mesh/incremental_mesher.h"
#include "core/scan/scan_to_level_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace sculpt::test {

double rampSample(double d) { return std::clamp(100.0 - 40.0 * d, 0.0, 200.0); }

vtkSmartPointer<vtkImageData> sampledImage(const openvdb::Coord& dims, const openvdb::Vec3d& spacing,
                                           const openvdb::Vec3d& origin,
                                           const std::function<double(const openvdb::Vec3d&)>& sdf)
{
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(dims.x(), dims.y(), dims.z());
    image->SetSpacing(spacing.x(), spacing.y(), spacing.z());
    image->SetOrigin(origin.x(), origin.y(), origin.z());
    image->AllocateScalars(VTK_SHORT, 1);
    auto* p = static_cast<short*>(image->GetScalarPointer());
    for (int k = 0; k < dims.z(); ++k) {
        for (int j = 0; j < dims.y(); ++j) {
            for (int i = 0; i < dims.x(); ++i)
                *p++ =
                    short(rampSample(sdf(origin + openvdb::Vec3d(i * spacing.x(), j * spacing.y(), k * spacing.z()))));
        }
    }
    return image;
}

std::pair<double, openvdb::Vec3d> sphereOf(const FieldImage& field)
{
    const TriangleMesh mesh = meshLevelSet(field);
    openvdb::Vec3d centre(0.0);
    for (const auto& p : mesh.positions) centre += openvdb::Vec3d(p[0], p[1], p[2]) / double(mesh.positions.size());
    double radius = 0.0;
    for (const auto& p : mesh.positions)
        radius += (openvdb::Vec3d(p[0], p[1], p[2]) - centre).length() / double(mesh.positions.size());
    return {radius, centre};
}

vtkSmartPointer<vtkImageData> SyntheticBall::image() const
{
    return sampledImage(dims, spacing, origin, [&](const openvdb::Vec3d& p) { return distance(p); });
}

void expectBallAt(const ScanVolume& scan, const SyntheticBall& ball, const std::string& format)
{
    const FieldImage field = scanToLevelSet(scan, 100.0, nativeVoxelSize(scan));
    EXPECT_NEAR(field.voxelSize(), std::min({ball.spacing.x(), ball.spacing.y(), ball.spacing.z()}), 1e-9) << format;
    const auto [radius, centre] = sphereOf(field);
    EXPECT_NEAR(radius, ball.radius, 0.5 * field.voxelSize()) << format;
    EXPECT_NEAR((centre - ball.centre).length(), 0.0, 0.5 * field.voxelSize())
        << format << " centre " << centre << " expected " << ball.centre;
}

void writeThreeLabelRaw(const std::filesystem::path& file)
{
    std::string bytes;
    for (int k = 0; k < 32; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 48; ++i) {
                const bool box = std::max({std::abs(i - 15.5), std::abs(j - 15.5), std::abs(k - 15.5)}) < 10.0;
                const bool inner = std::hypot(i - 15.5, j - 15.5, k - 15.5) < 5.0;
                bytes.push_back(inner ? 2 : box ? 1 : std::hypot(i - 31.5, j - 15.5, k - 15.5) < 6.0 ? 3 : 0);
            }
    std::ofstream(file, std::ios::binary) << bytes;
}

}  // namespace sculpt::test
