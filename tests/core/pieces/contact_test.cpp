// SPDX-License-Identifier: Apache-2.0
#include "core/io/mesh_import.h"
#include "core/mesh/incremental_mesher.h"
#include "core/pieces/contact.h"
#include "tests/support/cgal_data.h"

#include <gtest/gtest.h>
#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <random>

namespace sculpt {
namespace {

using openvdb::Mat4d;
using openvdb::Vec3d;

/// A CGAL mesh as a piece: its field (64 voxels across its longest side) and its surface.
struct Body {
    FieldImage field;
    IncrementalMesher mesher;
    double extent = 0.0;  ///< longest side
};

std::unique_ptr<Body> bodyOf(const std::string& name)
{
    const std::filesystem::path path = test::cgalMesh(name);
    if (path.empty()) return nullptr;
    const TriangleMesh mesh = readMesh(path);
    auto body = std::make_unique<Body>(Body{meshToField(mesh, voxelSizeFor(mesh, 64.0)), IncrementalMesher()});
    body->mesher.rebuild(body->field);
    body->extent = 64.0 * body->field.voxelSize();
    return body;
}

/// phi of `b` (placed at `pb`) at every vertex of `a`'s welded mesh (placed at `pa`): the brute force.
std::vector<double> depthsAtEveryVertex(const Body& a, const Mat4d& pa, const Body& b, const Mat4d& pb)
{
    const Mat4d toB = pa * pb.inverse();
    const auto accessor = b.field.grid().getConstAccessor();
    std::vector<double> phi;
    for (const auto& p : a.mesher.weldedMesh().positions) {
        const Vec3d index = b.field.grid().transform().worldToIndex(toB.transform(Vec3d(p[0], p[1], p[2])));
        phi.push_back(openvdb::tools::BoxSampler::sample(accessor, index));
    }
    return phi;
}

std::size_t countNegative(const std::vector<double>& values)
{
    return std::size_t(std::count_if(values.begin(), values.end(), [](double v) { return v < 0.0; }));
}

/// A random turn about a random axis, then a move within `reach` of the origin along each axis.
Mat4d randomPlacement(std::mt19937& random, double reach)
{
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Vec3d axis(normal(random), normal(random), normal(random));
    Mat4d m = openvdb::math::rotation<Mat4d>(axis.unitSafe(), 3.14159 * uniform(random));
    m.postTranslate(reach * Vec3d(uniform(random), uniform(random), uniform(random)));
    return m;
}

Mat4d movedBy(const Vec3d& offset)
{
    Mat4d m = Mat4d::identity();
    m.postTranslate(offset);
    return m;
}

}  // namespace

// The local boxes find exactly the vertices every vertex sampled finds, both ways, over a
// thousand placements of a cow and a figure eight (overlapping, nested, apart), while sampling
// fewer vertices than there are.
TEST(Contact, LocalBoxesFindWhatEveryVertexFindsOnAThousandPlacements)
{
    const auto cow = bodyOf("cow.off"), eight = bodyOf("eight.off");
    if (!cow || !eight) GTEST_SKIP() << "install libcgal-demo";
    std::mt19937 random(33);
    const double reach = 0.3 * (cow->extent + eight->extent);
    std::size_t overlapping = 0, apart = 0, sampled = 0, vertices = 0;
    const std::size_t cowVertices = cow->mesher.weldedMesh().positions.size();
    for (int i = 0; i < 1000; ++i) {
        const Mat4d pc = randomPlacement(random, reach), pe = randomPlacement(random, 0.2 * reach);
        const Penetration found = penetration({cow->field, cow->mesher, pc}, {eight->field, eight->mesher, pe});
        const std::size_t brute = countNegative(depthsAtEveryVertex(*cow, pc, *eight, pe));
        ASSERT_EQ(found.penetratingVertices, brute) << "placement " << i;
        const Penetration back = penetration({eight->field, eight->mesher, pe}, {cow->field, cow->mesher, pc});
        ASSERT_EQ(back.penetratingVertices, countNegative(depthsAtEveryVertex(*eight, pe, *cow, pc))) << i;
        (found.any() || back.any() ? overlapping : apart) += 1;
        sampled += found.sampledVertices;
        vertices += cowVertices;
    }
    EXPECT_GT(overlapping, 200u);
    EXPECT_GT(apart, 200u);
    EXPECT_LT(double(sampled), 0.5 * double(vertices));
}

TEST(Contact, PiecesApartSampleNothing)
{
    const auto cow = bodyOf("cow.off"), eight = bodyOf("eight.off");
    if (!cow || !eight) GTEST_SKIP() << "install libcgal-demo";
    const Mat4d far = movedBy(Vec3d(2.0 * (cow->extent + eight->extent), 0.0, 0.0));
    const Penetration none = overlap({cow->field, cow->mesher, far}, {eight->field, eight->mesher});
    EXPECT_EQ(none.sampledVertices, 0u);
    EXPECT_FALSE(none.any());
}

// A cow sent through a figure eight stops where they touch: no vertex of either inside the other,
// the nearest within half a voxel.
TEST(Contact, AMoveStopsAtContactWithinHalfAVoxel)
{
    const auto cow = bodyOf("cow.off"), eight = bodyOf("eight.off");
    if (!cow || !eight) GTEST_SKIP() << "install libcgal-demo";
    const Vec3d start(-1.5 * (cow->extent + eight->extent), 0.1 * eight->extent, 0.0);
    const auto along = [&](double t) { return movedBy(start * (1.0 - t)); };
    const double t = freeFraction({cow->field, cow->mesher}, {eight->field, eight->mesher}, along);
    ASSERT_GT(t, 0.0);
    ASSERT_LT(t, 1.0);
    const std::vector<double> cowInEight = depthsAtEveryVertex(*cow, along(t), *eight, Mat4d::identity());
    const std::vector<double> eightInCow = depthsAtEveryVertex(*eight, Mat4d::identity(), *cow, along(t));
    const double nearest = std::min(*std::min_element(cowInEight.begin(), cowInEight.end()),
                                    *std::min_element(eightInCow.begin(), eightInCow.end()));
    EXPECT_GE(nearest, 0.0);
    EXPECT_LT(nearest, 0.5 * std::min(cow->field.voxelSize(), eight->field.voxelSize()));
}

}  // namespace sculpt
