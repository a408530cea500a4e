// SPDX-License-Identifier: Apache-2.0
// Ray-traced renders of analytic shapes: coverage against the projected disc, depth against the
// distance to the sphere, normals, determinism across thread counts, framing, and the warnings.

#include "core/base/errors.h"
#include "core/primitives/analytic_shapes.h"
#include "core/render/ray_tracer.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

namespace sculpt {
namespace {

using openvdb::Vec3d;

constexpr double kRadius = 10.0, kVoxel = 0.25, kDistance = 40.0, kFov = 30.0;

struct SphereRender {
    FieldImage field = makeSphere(kRadius, kVoxel);
    Camera camera;
    RenderOptions options;
    SphereRender()
    {
        camera.position = Vec3d(0.0, 0.0, kDistance);
        camera.fovDegrees = kFov;
        options.width = options.height = 160;
        options.samples = 16;
        options.occlusionRays = 0;
        options.background.reset();  // transparent: alpha is coverage
    }
    RenderedImage render(RenderReport& report) const { return renderField(field, camera, options, report); }
};

TEST(RayTracer, SphereCoverageDepthAndNormalsMatchTheAnalyticSphere)
{
    const SphereRender s;
    RenderReport report;
    const RenderedImage image = s.render(report);
    EXPECT_TRUE(report.warnings.empty());
    // The silhouette of a sphere seen on axis: a disc of angular radius asin(r / d).
    const double focalPixels = 0.5 * image.height / std::tan(0.5 * kFov * M_PI / 180.0);
    const double discRadius = focalPixels * std::tan(std::asin(kRadius / kDistance));
    double coverage = 0.0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) coverage += image.rgba[4 * i + 3];
    EXPECT_NEAR(coverage, M_PI * discRadius * discRadius, 0.01 * M_PI * discRadius * discRadius);

    // The pixels at the centre see the sphere's nearest point, d - r away.
    const std::size_t centre = std::size_t(image.height / 2) * std::size_t(image.width) + std::size_t(image.width / 2);
    EXPECT_NEAR(image.depth[centre], kDistance - kRadius, 0.5 * kVoxel);

    const PinholeProjection projection(s.camera, image.width, image.height);
    int covered = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
            const float alpha = image.rgba[4 * i + 3];
            if (alpha == 0.0f) {
                EXPECT_TRUE(std::isinf(image.depth[i]));
                continue;
            }
            ++covered;
            const Vec3d n(image.normal[3 * i], image.normal[3 * i + 1], image.normal[3 * i + 2]);
            ASSERT_NEAR(n.length(), 1.0, 1e-3) << x << ", " << y;
            const Vec3d towardsCamera = -projection.ray(x + 0.5, y + 0.5).dir();
            // Fully covered pixels face the camera; the silhouette's mean normal may graze it.
            ASSERT_GT(n.dot(towardsCamera), alpha == 1.0f ? 0.0 : -0.05) << x << ", " << y;
        }
    }
    EXPECT_EQ(std::size_t(covered), report.coveredPixels);
}

TEST(RayTracer, OneAndTwoThreadsGiveTheSameImageBitForBit)
{
    SphereRender s;
    s.options.occlusionRays = 4;
    s.options.samples = 4;
    s.options.background = Vec3d(0.2, 0.3, 0.4);
    s.camera.position = Vec3d(25.0, 15.0, 30.0);
    RenderReport report;
    RenderedImage one, two;
    {
        tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
        one = s.render(report);
    }
    {
        tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
        two = s.render(report);
    }
    EXPECT_EQ(one.rgba, two.rgba);
    EXPECT_EQ(one.depth, two.depth);
    EXPECT_EQ(one.normal, two.normal);
}

TEST(RayTracer, OcclusionDarkensTheInsideOfATorusHoleAndSparesAConvexShape)
{
    // Seen from above, the hole's inner wall faces the other side of the ring; the outer rim
    // faces open space. A sphere occludes nothing of itself.
    Camera camera;
    camera.position = Vec3d(0.0, 0.0, 60.0);
    camera.fovDegrees = 40.0;
    RenderOptions options;
    options.width = options.height = 96;
    options.samples = 4;
    options.occlusionReach = 1.0;
    const auto lossAlongMiddleRow = [&](const FieldImage& field, double innerBelow, double outerAbove) {
        RenderReport report;
        options.occlusionRays = 0;
        const RenderedImage open = renderField(field, camera, options, report);
        options.occlusionRays = 32;
        const RenderedImage occluded = renderField(field, camera, options, report);
        const PinholeProjection projection(camera, options.width, options.height);
        double innerLoss = 0.0, outerLoss = 0.0;
        int inner = 0, outer = 0;
        const int y = options.height / 2;
        for (int x = 0; x < options.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(options.width) + std::size_t(x);
            if (!(open.rgba[4 * i + 1] > 0.0f) || std::isinf(open.depth[i])) continue;
            const Vec3d hit = camera.position + projection.ray(x + 0.5, y + 0.5).dir() * double(open.depth[i]);
            const double fromAxis = std::hypot(hit.x(), hit.y());
            const double loss = 1.0 - occluded.rgba[4 * i + 1] / open.rgba[4 * i + 1];
            EXPECT_GE(loss, -1e-6) << "occlusion brightened pixel " << x;
            if (fromAxis < innerBelow) innerLoss += loss, ++inner;
            if (fromAxis > outerAbove) outerLoss += loss, ++outer;
        }
        EXPECT_GT(inner, 2);
        EXPECT_GT(outer, 2);
        return std::pair{innerLoss / std::max(inner, 1), outerLoss / std::max(outer, 1)};
    };
    const auto [innerWall, outerRim] = lossAlongMiddleRow(makeTorus(10.0, 4.0, 0.25), 8.0, 12.0);
    EXPECT_GT(innerWall, outerRim + 0.02);
    const auto [sphereCentre, sphereEdge] = lossAlongMiddleRow(makeSphere(10.0, 0.25), 5.0, 5.0);
    EXPECT_NEAR(sphereCentre, 0.0, 1e-6);
    EXPECT_NEAR(sphereEdge, 0.0, 1e-6);
}

TEST(RayTracer, FramingCameraSeesTheWholeModelAndFillsTheView)
{
    const FieldImage box = makeBox(6.0, 0.25);
    RenderOptions options;
    options.width = 160;
    options.height = 100;
    options.samples = 1;
    options.occlusionRays = 0;
    options.background.reset();
    const Camera camera = framingCamera(SurfaceExtent(box), double(options.width) / options.height);
    RenderReport report;
    const RenderedImage image = renderField(box, camera, options, report);
    int top = image.height, bottom = -1, left = image.width, right = -1;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (image.rgba[4 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) + 3] == 0.0f) continue;
            top = std::min(top, y), bottom = std::max(bottom, y);
            left = std::min(left, x), right = std::max(right, x);
        }
    }
    // Nothing touches the border, and the model spans most of the narrower side.
    EXPECT_GT(top, 0);
    EXPECT_LT(bottom, image.height - 1);
    EXPECT_GT(left, 0);
    EXPECT_LT(right, image.width - 1);
    EXPECT_GT(bottom - top, image.height / 2);
}

TEST(RayTracer, WarnsWhenInsideOrLookingAwayAndRefusesAbsurdSizes)
{
    SphereRender s;
    s.options.width = s.options.height = 16;
    RenderReport inside;
    s.camera.position = Vec3d(1.0, 0.0, 0.0);
    s.render(inside);
    ASSERT_FALSE(inside.warnings.empty());
    EXPECT_NE(inside.warnings.front().find("inside"), std::string::npos);

    RenderReport away;
    s.camera.position = Vec3d(0.0, 0.0, kDistance);
    s.camera.lookAt = Vec3d(0.0, 0.0, 2.0 * kDistance);
    const RenderedImage empty = s.render(away);
    ASSERT_FALSE(away.warnings.empty());
    EXPECT_NE(away.warnings.back().find("sees nothing"), std::string::npos);
    EXPECT_EQ(away.coveredPixels, 0u);
    EXPECT_TRUE(std::isinf(empty.depth[0]));

    RenderReport ignored;
    for (const auto& [w, h] : {std::pair{0, 10}, std::pair{10, -1}, std::pair{RenderOptions::kMaxSide + 1, 10}}) {
        s.options.width = w;
        s.options.height = h;
        EXPECT_THROW(s.render(ignored), InputError) << w << " x " << h;
    }
    s.options.width = s.options.height = 16;
    s.camera.lookAt = s.camera.position;
    EXPECT_THROW(s.render(ignored), InputError);
}

}  // namespace
}  // namespace sculpt
