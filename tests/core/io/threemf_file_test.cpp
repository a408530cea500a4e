// SPDX-License-Identifier: Apache-2.0
// 3MF files as the 3MF Consortium's own library (lib3mf) reads them: every object with its name,
// size and colour, a build item each, the unit the document says.

#include "core/base/errors.h"
#include "core/io/threemf_file.h"
#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/file_bytes.h"
#include "tests/support/temp_dir.h"
#include "tests/support/threemf_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sculpt {
namespace {

using test::TempDir;

TriangleMesh ballMesh(double radius, double shiftZ)
{
    TriangleMesh mesh = meshLevelSet(rasterizeSdf(sphereSdf(radius), 0.5));
    for (auto& p : mesh.positions) p[2] += float(shiftZ);
    return mesh;
}

TEST(ThreeMfFile, LibThreeMfReadsEveryObjectWithItsNameSizeAndColour)
{
    TempDir dir;
    const TriangleMesh small = ballMesh(3.0, 0.0), large = ballMesh(5.0, 20.0), third = ballMesh(2.0, -10.0);
    const std::vector<ThreeMfObject> objects{{"skull", &small, {1.0f, 0.5f, 0.0f}},
                                             {"jaw & <teeth> \"left\"", &large, {0.0f, 0.25f, 1.0f}},
                                             {"label 3", &third, {0.2f, 0.8f, 0.2f}}};
    writeThreeMf(objects, dir / "parts.3mf", "mm");
    const test::ThreeMfModel model = test::readThreeMf(dir / "parts.3mf");
    ASSERT_TRUE(model.read);
    EXPECT_EQ(model.unit, 1);  // millimetres
    ASSERT_EQ(model.objects.size(), 3u);
    EXPECT_EQ(model.buildItems, 3u);
    const std::array<std::array<std::uint8_t, 3>, 3> colours{{{255, 128, 0}, {0, 64, 255}, {51, 204, 51}}};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(model.objects[i].name, objects[i].name);
        EXPECT_EQ(model.objects[i].vertices, objects[i].mesh->positions.size());
        EXPECT_EQ(model.objects[i].triangles, objects[i].mesh->triangles.size());
        EXPECT_EQ(model.objects[i].colour, colours[i]) << i;
    }
    EXPECT_NEAR(model.objects[1].minZ, 15.0, 0.1);  // positions as written, where the piece sits
    EXPECT_NEAR(model.objects[1].maxZ, 25.0, 0.1);
    // The same objects give the same bytes (no clock in the archive).
    writeThreeMf(objects, dir / "again.3mf", "mm");
    EXPECT_TRUE(test::fileBytes(dir / "again.3mf") == test::fileBytes(dir / "parts.3mf"));
}

TEST(ThreeMfFile, TheDocumentsUnitOrARefusal)
{
    TempDir dir;
    const TriangleMesh ball = ballMesh(2.0, 0.0);
    writeThreeMf({{"ball", &ball, {0.8f, 0.8f, 0.8f}}}, dir / "cm.3mf", "cm");
    EXPECT_EQ(test::readThreeMf(dir / "cm.3mf").unit, 2);
    writeThreeMf({{"ball", &ball, {0.8f, 0.8f, 0.8f}}}, dir / "in.3mf", "in");
    EXPECT_EQ(test::readThreeMf(dir / "in.3mf").unit, 3);
    EXPECT_THROW(writeThreeMf({{"ball", &ball, {0.8f, 0.8f, 0.8f}}}, dir / "voxel.3mf", "voxel"), InputError);
    TriangleMesh broken = ball;
    broken.positions[7][1] = std::numeric_limits<float>::infinity();
    EXPECT_THROW(writeThreeMf({{"ball", &broken, {0.8f, 0.8f, 0.8f}}}, dir / "inf.3mf", "mm"), InputError);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"cm.3mf", "in.3mf"}));
}

}  // namespace
}  // namespace sculpt
