// SPDX-License-Identifier: Apache-2.0
#include "core/local/band_redistance.h"

#include "core/field/band_rule.h"
#include "core/field/dense_gather.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace sculpt {

namespace {

/// A dense copy of a box of the grid with index arithmetic.
struct DenseBox {
    openvdb::CoordBBox box;
    openvdb::Coord dim;
    std::vector<float> values;

    explicit DenseBox(const openvdb::CoordBBox& b) : box(b), dim(b.dim()), values(size_t(b.volume())) {}
    size_t index(int x, int y, int z) const { return denseIndex(dim.y(), dim.z(), x, y, z); }
    openvdb::Coord coord(int x, int y, int z) const { return box.min().offsetBy(x, y, z); }
};

/// Smaller magnitude of the two face neighbours along each axis that share phi's sign (or
/// infinity): the upwind values of the Eikonal equation.
openvdb::Vec3d upwindMagnitudes(const DenseBox& d, const std::vector<float>& v, int x, int y, int z, bool inside)
{
    const std::ptrdiff_t stride[3] = {std::ptrdiff_t(d.dim.y()) * d.dim.z(), d.dim.z(), 1};
    const size_t i = d.index(x, y, z);
    openvdb::Vec3d a;
    for (int axis = 0; axis < 3; ++axis) {
        double best = std::numeric_limits<double>::infinity();
        for (const std::ptrdiff_t s : {-stride[axis], stride[axis]}) {
            const float n = v[size_t(std::ptrdiff_t(i) + s)];
            if ((n < 0.0f) == inside) best = std::min(best, double(std::abs(n)));
        }
        a[axis] = best;
    }
    return a;
}

/// First-order Eikonal solution |grad u| = 1 from upwind magnitudes a (h = voxel size).
double eikonal(openvdb::Vec3d a, double h)
{
    std::sort(&a[0], &a[0] + 3);
    double u = a[0] + h;
    if (u > a[1]) {
        const double s = a[0] + a[1];
        u = 0.5 * (s + std::sqrt(std::max(0.0, 2.0 * h * h - (a[0] - a[1]) * (a[0] - a[1]))));
        if (u > a[2]) {
            const double sum = a[0] + a[1] + a[2];
            const double sq = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
            u = (sum + std::sqrt(std::max(0.0, sum * sum - 3.0 * (sq - h * h)))) / 3.0;
        }
    }
    return u;
}

/// Godunov's upwind |grad phi| (first order) for a speed of sign `sign`.
double godunovGradient(const DenseBox& d, const std::vector<float>& v, int x, int y, int z, double sign, double invH)
{
    const float c = v[d.index(x, y, z)];
    const float n[3][2] = {{v[d.index(x - 1, y, z)], v[d.index(x + 1, y, z)]},
                           {v[d.index(x, y - 1, z)], v[d.index(x, y + 1, z)]},
                           {v[d.index(x, y, z - 1)], v[d.index(x, y, z + 1)]}};
    double sum = 0.0;
    for (const auto& pair : n) {
        const double minus = (c - pair[0]) * invH, plus = (pair[1] - c) * invH;
        if (sign > 0.0) {
            sum += std::max(std::max(minus, 0.0) * std::max(minus, 0.0), std::min(plus, 0.0) * std::min(plus, 0.0));
        } else {
            sum += std::max(std::min(minus, 0.0) * std::min(minus, 0.0), std::max(plus, 0.0) * std::max(plus, 0.0));
        }
    }
    return std::sqrt(sum);
}

/// Writes `update(x, y, z)` (when it returns a value) to `to` for the box's interior voxels
/// inside the zone, x-slabs in parallel. Updates test their cheap conditions before calling
/// `inZone`, which most voxels of the box (far from the band) never need.
template <typename UpdateFn>
void sweep(const DenseBox& d, std::vector<float>& to, const UpdateFn& update)
{
    tbb::parallel_for(1, d.dim.x() - 1, [&](int x) {
        for (int y = 1; y < d.dim.y() - 1; ++y) {
            for (int z = 1; z < d.dim.z() - 1; ++z) {
                if (const std::optional<float> value = update(x, y, z)) to[d.index(x, y, z)] = *value;
            }
        }
    });
}

}  // namespace

void redistanceBand(openvdb::FloatGrid& grid, const Capsule& zone)
{
    const auto& xform = grid.transform();
    const double h = xform.voxelSize()[0], invH = 1.0 / h;
    const float background = grid.background();
    openvdb::BBoxd world(openvdb::math::minComponent(zone.from, zone.to),
                         openvdb::math::maxComponent(zone.from, zone.to));
    world.expand(zone.radius);
    openvdb::CoordBBox box(xform.worldToIndexCellCentered(world.min()), xform.worldToIndexCellCentered(world.max()));
    box.expand(1);  // apron: read, never written
    DenseBox d(box);
    gatherDense(grid.tree(), box, d.values.data());

    const Capsule indexZone = zone.inIndexSpace(xform);
    std::vector<float> normalised = d.values;
    const auto inZone = [&](int x, int y, int z) { return indexZone.contains(d.coord(x, y, z).asVec3d()); };
    sweep(d, normalised, [&](int x, int y, int z) -> std::optional<float> {
        const float phi = d.values[d.index(x, y, z)];
        if (std::abs(phi) >= background || !inZone(x, y, z)) return std::nullopt;
        const double sign = phi / std::sqrt(double(phi) * phi + h * h);
        return float(phi - 0.3 * h * sign * (godunovGradient(d, d.values, x, y, z, sign, invH) - 1.0));
    });
    std::vector<float> extended = normalised;
    sweep(d, extended, [&](int x, int y, int z) -> std::optional<float> {
        const float phi = normalised[d.index(x, y, z)];
        if (std::abs(phi) < background) return std::nullopt;
        const bool inside = phi < 0.0f;
        const openvdb::Vec3d upwind = upwindMagnitudes(d, normalised, x, y, z, inside);
        if (std::min({upwind[0], upwind[1], upwind[2]}) >= background || !inZone(x, y, z)) return std::nullopt;
        const float magnitude = float(std::min(eikonal(upwind, h), double(background)));
        return inside ? -magnitude : magnitude;
    });

    // Write back what changed; the tree's structure changes in this one thread.
    auto acc = grid.getAccessor();
    for (int x = 1; x < d.dim.x() - 1; ++x) {
        for (int y = 1; y < d.dim.y() - 1; ++y) {
            for (int z = 1; z < d.dim.z() - 1; ++z) {
                const size_t i = d.index(x, y, z);
                const float value = std::clamp(extended[i], -background, background);
                if (value == d.values[i]) continue;  // only zone voxels can differ
                const openvdb::Coord ijk = d.coord(x, y, z);
                setBandValue(acc, ijk, toBand(value, background));
            }
        }
    }
}

}  // namespace sculpt
