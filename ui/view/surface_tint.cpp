// SPDX-License-Identifier: Apache-2.0
#include "ui/view/surface_tint.h"

#include "core/solids/wall_thickness.h"
#include "ui/view/surface_look.h"

#include <openvdb/tools/Interpolation.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace sculpt::ui {

namespace {

using Colour = std::array<double, 3>;

Colour mix(const Colour& a, const Colour& b, double t)
{
    return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

/// How strongly the check flags a point, 0 (not at all) to 1.
double flagged(const SurfaceTint& tint, const openvdb::Vec3d& p, const openvdb::Vec3d& normal)
{
    if (tint.check == SurfaceTint::Check::Thickness && tint.surface) {
        const std::optional<double> t = wallThicknessAt(*tint.surface, p, normal, tint.thinnerThan);
        return t ? 1.0 - 0.6 * (*t / tint.thinnerThan) : 0.0;
    }
    if (tint.check == SurfaceTint::Check::Overhang) {
        const std::optional<double> angle = overhangDegrees(normal, tint.up);
        return angle && *angle < tint.steeperThan ? 1.0 - 0.6 * (*angle / tint.steeperThan) : 0.0;
    }
    return 0.0;
}

}  // namespace

const char* checkName(SurfaceTint::Check check)
{
    switch (check) {
    case SurfaceTint::Check::Thickness: return "Wall Thickness";
    case SurfaceTint::Check::Overhang: return "Overhang";
    case SurfaceTint::Check::None: break;
    }
    return "None";
}

void tintPoints(vtkPolyData& poly, const BlockMesh& mesh, const SurfaceTint& tint)
{
    constexpr double kMaskedShade = 0.3;  // of the clay, where fully masked
    const Colour clay{kClayColour[0], kClayColour[1], kClayColour[2]};
    const Colour heat = tint.check == SurfaceTint::Check::Thickness ? Colour{0.95, 0.1, 0.05} : Colour{0.1, 0.3, 0.95};
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetName("Tint");
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(vtkIdType(mesh.positions.size()));
    std::optional<openvdb::FloatGrid::ConstAccessor> mask;
    if (tint.mask) mask.emplace(tint.mask->getConstAccessor());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const auto& q = mesh.positions[i];
        const auto& n = mesh.normals[i];
        const openvdb::Vec3d p(q[0], q[1], q[2]), normal = openvdb::Vec3d(n[0], n[1], n[2]).unitSafe();
        Colour colour = mix(clay, heat, flagged(tint, p, normal));
        if (mask) {
            const openvdb::Vec3d index = tint.mask->transform().worldToIndex(p);
            const double m = std::clamp(double(openvdb::tools::BoxSampler::sample(*mask, index)), 0.0, 1.0);
            for (double& c : colour) c *= 1.0 - (1.0 - kMaskedShade) * m;
        }
        for (int c = 0; c < 3; ++c)
            colours->SetValue(
                vtkIdType(3 * i + std::size_t(c)),
                static_cast<unsigned char>(std::lround(255.0 * std::clamp(colour[std::size_t(c)], 0.0, 1.0))));
    }
    poly.GetPointData()->SetScalars(colours);
}

}  // namespace sculpt::ui
