// SPDX-License-Identifier: Apache-2.0
// The coarse preview the window shows while a large document is meshed: a closed surface near
// the true one, with about stride^2 fewer triangles, and the stride chosen from the budget.

#include "core/mesh/incremental_mesher.h"
#include "core/mesh/preview_mesh.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/mesh_checks.h"

#include <gtest/gtest.h>

namespace sculpt {
namespace {

constexpr double kPi = 3.14159265358979323846;

class PreviewMesh : public ::testing::TestWithParam<int> {};

TEST_P(PreviewMesh, IsAClosedSurfaceWithinACoarseVoxelOfTheSphere)
{
    const int stride = GetParam();
    const double r = 40.0, h = 0.5;  // 80 voxels: 10 coarse voxels at stride 8
    const FieldImage field = makeSphere(r, h);
    const TriangleMesh full = meshLevelSet(field), preview = previewMesh(field, stride);
    const test::MeshTopology t = test::meshTopology(preview);
    EXPECT_TRUE(t.closedManifold()) << t.boundaryEdges << " boundary, " << t.nonManifoldEdges << " non-manifold";
    EXPECT_EQ(t.eulerCharacteristic(), 2);
    double worst = 0.0;
    for (const auto& p : preview.positions)
        worst = std::max(worst, std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - r));
    EXPECT_LT(worst, stride * h);
    EXPECT_NEAR(test::meshArea(preview), 4.0 * kPi * r * r, 0.05 * 4.0 * kPi * r * r);
    const double shrink = double(full.triangles.size()) / double(preview.triangles.size());
    EXPECT_GT(shrink, 0.7 * stride * stride);
    EXPECT_LT(shrink, 1.4 * stride * stride);
}

INSTANTIATE_TEST_SUITE_P(Strides, PreviewMesh, ::testing::Values(1, 2, 4, 8),
                         [](const auto& test) { return "s" + std::to_string(test.param); });

TEST(PreviewStride, FollowsTheTriangleBudget)
{
    const FieldImage field = makeSphere(40.0, 0.5);
    const std::size_t triangles = meshLevelSet(field).triangles.size();
    EXPECT_EQ(previewStride(field, 2 * triangles), 1);  // the full mesh fits: no preview
    // A preview at the chosen stride fits the budget (the estimate is within a factor of two).
    for (const std::size_t budget : {triangles / 3, triangles / 12, triangles / 50}) {
        const int stride = previewStride(field, budget);
        EXPECT_GT(stride, 1);
        EXPECT_LT(previewMesh(field, stride).triangles.size(), 2 * budget) << "stride " << stride;
        EXPECT_GT(previewMesh(field, stride / 2).triangles.size(), budget / 2) << "a finer stride fitted too";
    }
    EXPECT_THROW(previewMesh(field, 3), std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
