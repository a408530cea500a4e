// SPDX-License-Identifier: Apache-2.0
// Fast marching on a dense box (core/fast_marching.h): exact on planes, first-order accurate on
// spheres, seeds untouched, faces left alone, marching stops at its limit.

#include "core/scan/fast_marching.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sculpt {
namespace {

constexpr float kFar = std::numeric_limits<float>::infinity();

struct Box {
    openvdb::math::Coord dims;
    std::vector<float> distance;

    explicit Box(int n) : dims(n, n, n), distance(size_t(n) * n * n, kFar) {}
    size_t index(int x, int y, int z) const { return (size_t(z) * dims.y() + size_t(y)) * dims.x() + size_t(x); }
};

/// Seeds the voxels next to a surface given by its signed distance `sdf` (voxel units) with
/// their exact distances, as the scan importer seeds the voxels next to a crossing.
template <typename Sdf>
void seedExact(Box& box, Sdf sdf)
{
    const int n = box.dims.x();
    for (int z = 1; z < n - 1; ++z) {
        for (int y = 1; y < n - 1; ++y) {
            for (int x = 1; x < n - 1; ++x) {
                const double d = sdf(x, y, z);
                bool crossing = false;
                for (const auto& o :
                     {openvdb::math::Coord(1, 0, 0), openvdb::math::Coord(0, 1, 0), openvdb::math::Coord(0, 0, 1)}) {
                    crossing = crossing || (sdf(x + o.x(), y + o.y(), z + o.z()) < 0) != (d < 0) ||
                               (sdf(x - o.x(), y - o.y(), z - o.z()) < 0) != (d < 0);
                }
                if (!crossing) continue;
                box.distance[box.index(x, y, z)] = float(std::abs(d));
            }
        }
    }
}

TEST(FastMarching, PlaneDistancesAreExact)
{
    Box box(24);
    const auto plane = [](int x, int, int) { return x - 10.3; };
    seedExact(box, plane);
    FastMarching().run(box.dims, 1.0f, 6.0f, box.distance);
    for (int z = 1; z < 23; ++z) {
        for (int y = 1; y < 23; ++y) {
            for (int x = 1; x < 23; ++x) {
                const float d = box.distance[box.index(x, y, z)];
                if (std::abs(plane(x, y, z)) < 5.9) {
                    EXPECT_NEAR(d, std::abs(plane(x, y, z)), 1e-5) << x << " " << y << " " << z;
                } else {
                    EXPECT_GE(d, 6.0f) << "beyond the limit " << x;
                }
            }
        }
    }
}

TEST(FastMarching, SphereDistancesAreFirstOrderAccurate)
{
    for (const float h : {1.0f, 0.25f}) {  // distances scale with the voxel size
        Box box(40);
        const double radius = 11.7;
        const auto sphere = [&](int x, int y, int z) {
            return std::sqrt((x - 19.6) * (x - 19.6) + (y - 20.2) * (y - 20.2) + (z - 19.9) * (z - 19.9)) - radius;
        };
        seedExact(box, sphere);
        for (float& d : box.distance) d *= h;
        FastMarching().run(box.dims, h, 3.0f * h, box.distance);
        double worst = 0.0, sum = 0.0;
        int count = 0;
        for (int z = 1; z < 39; ++z) {
            for (int y = 1; y < 39; ++y) {
                for (int x = 1; x < 39; ++x) {
                    const double exact = std::abs(sphere(x, y, z));
                    if (exact >= 2.9) continue;
                    const double error = box.distance[box.index(x, y, z)] / h - exact;
                    worst = std::max(worst, std::abs(error));
                    sum += std::abs(error);
                    ++count;
                }
            }
        }
        EXPECT_LT(worst, 0.2) << "voxels, h " << h;
        EXPECT_LT(sum / count, 0.05) << "voxels, h " << h;
    }
}

TEST(FastMarching, SeedsKeepTheirValuesAndFacesAreLeftAlone)
{
    Box box(8);
    const size_t seed = box.index(3, 3, 3), close = box.index(4, 3, 3), next = box.index(3, 4, 3);
    box.distance[seed] = 0.2f;
    box.distance[close] = 0.9f;  // below what marching from the first seed gives (1.2): kept
    FastMarching().run(box.dims, 1.0f, 3.0f, box.distance);
    EXPECT_FLOAT_EQ(box.distance[seed], 0.2f);
    EXPECT_FLOAT_EQ(box.distance[close], 0.9f);
    EXPECT_FLOAT_EQ(box.distance[next], 1.2f) << "one axis: the seed's distance plus a voxel";
    EXPECT_EQ(box.distance[box.index(0, 3, 3)], kFar) << "faces only border the march";
}

}  // namespace
}  // namespace sculpt
