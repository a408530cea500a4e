// SPDX-License-Identifier: Apache-2.0
// The generated marching-cubes table: every configuration and every ambiguous face pair closes.

#include "core/mesh/incremental_mesher.h"
#include "core/mesh/marching_cubes_table.h"
#include "tests/support/grid_builders.h"
#include "tests/support/mesh_checks.h"

#include <gtest/gtest.h>

#include <iostream>
#include <random>

namespace sculpt {
namespace {

using test::fieldFromVoxels;
using test::meshTopology;

/// Corner c of the cube at `base`: inside (negative) iff bit c of `cube` is set.
void setCube(std::map<openvdb::Coord, float>& values, const openvdb::Coord& base, unsigned cube, std::mt19937& random)
{
    std::uniform_real_distribution<float> magnitude(0.05f, 1.0f);
    for (int c = 0; c < 8; ++c) {
        const float v = magnitude(random);
        values[base.offsetBy(c & 1, c >> 1 & 1, c >> 2 & 1)] = (cube >> c & 1) ? -v : v;
    }
}

void expectClosed(const std::map<openvdb::Coord, float>& values, const std::string& what)
{
    const TriangleMesh mesh = meshLevelSet(fieldFromVoxels(values));
    const test::MeshTopology t = meshTopology(mesh);
    ASSERT_TRUE(t.closedManifold()) << what << ": boundary " << t.boundaryEdges << ", non-manifold "
                                    << t.nonManifoldEdges << ", misoriented " << t.misorientedEdges;
    ASSERT_EQ(t.eulerCharacteristic() % 2, 0) << what;
    ASSERT_GT(test::meshVolume(mesh), 0.0) << what << ": triangles face inwards";
}

TEST(MarchingCubesTable, TrianglesUseOnlyCrossingEdges)
{
    int withCentre = 0;
    for (unsigned cube = 0; cube < 256; ++cube) {
        const mc::Case& info = mc::cubeCase(cube);
        for (unsigned bits = 0; bits < (1u << info.ambiguousFaceCount); ++bits) {
            const mc::Triangulation& t = info.triangulation(bits);
            std::array<int, 12> uses{};
            for (int i = 0; i < t.triangleCount; ++i) {
                for (int e : t.edges[i]) {
                    if (e == mc::kCentre) continue;
                    const int lower = mc::edgeCorner(e), upper = lower | 1 << mc::edgeAxis(e);
                    EXPECT_NE(cube >> lower & 1, cube >> upper & 1) << "case " << cube;
                    ++uses[size_t(e)];
                }
            }
            int crossing = 0;
            for (int e = 0; e < 12; ++e) {
                const int lower = mc::edgeCorner(e), upper = lower | 1 << mc::edgeAxis(e);
                if ((cube >> lower & 1) != (cube >> upper & 1)) {
                    ++crossing;
                    EXPECT_GT(uses[size_t(e)], 0) << "case " << cube << " misses edge " << e;
                }
            }
            // Loops of n vertices give n - 2 triangles each, n around a centre vertex.
            if (crossing > 0) {
                EXPECT_LE(t.triangleCount, crossing - 2 + (t.centreLoopSize ? 2 : 0));
            }
            if (t.centreLoopSize) {
                ++withCentre;
                EXPECT_GE(t.centreLoopSize, 6) << "case " << cube;  // small loops never need one
            }
        }
    }
    std::cout << withCentre << " triangulations use a centre vertex\n";
    EXPECT_EQ(mc::cubeCase(0).triangulation(0).triangleCount, 0);
    EXPECT_EQ(mc::cubeCase(1).triangulation(0).triangleCount, 1);
    EXPECT_EQ(mc::cubeCase(0x69).ambiguousFaceCount, 6);  // the checkerboard configuration
}

TEST(MarchingCubes, EveryConfigurationClosesInsideOutsideCells)
{
    std::mt19937 random(7);
    for (unsigned cube = 1; cube < 256; ++cube) {
        for (int trial = 0; trial < 6; ++trial) {  // random magnitudes flip ambiguous decisions
            std::map<openvdb::Coord, float> values;
            setCube(values, openvdb::Coord(0), cube, random);
            expectClosed(values, "case " + std::to_string(cube) + " trial " + std::to_string(trial));
        }
    }
}

TEST(MarchingCubes, CubePairsSharingAnAmbiguousFaceClose)
{
    std::mt19937 random(11);
    std::uniform_int_distribution<unsigned> anyCube(0, 255);
    for (int axis = 0; axis < 3; ++axis) {
        openvdb::Coord step(0);
        step[axis] = 1;
        const mc::Face& shared = mc::face(axis * 2 + 1);  // high face of the first cube
        for (int pattern = 0; pattern < 2; ++pattern) {
            for (int trial = 0; trial < 200; ++trial) {
                unsigned first = anyCube(random);
                for (int k = 0; k < 4; ++k) {  // force the checkerboard on the shared face
                    const unsigned bit = 1u << shared.corners[size_t(k)];
                    first = (k + pattern) % 2 ? (first | bit) : (first & ~bit);
                }
                std::map<openvdb::Coord, float> values;
                setCube(values, openvdb::Coord(0), first, random);
                std::map<openvdb::Coord, float> second;
                setCube(second, step, anyCube(random), random);
                for (const auto& [ijk, v] : values) second[ijk] = v;  // shared face: cube one's values
                expectClosed(second, "axis " + std::to_string(axis) + " pattern " + std::to_string(pattern) +
                                         " trial " + std::to_string(trial));
            }
        }
    }
}

}  // namespace
}  // namespace sculpt
