// SPDX-License-Identifier: Apache-2.0
// Rays against the level set: agreement with OpenVDB's LevelSetRayIntersector, and the surface
// as it was before a journal's edits, read without a copy.

#include "core/brushes/brush.h"
#include "core/field/surface_ray.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>
#include <openvdb/tools/RayIntersector.h>

#include <random>

namespace sculpt {
namespace {

openvdb::CoordBBox leafBox(const FieldImage& field)
{
    openvdb::CoordBBox box;
    field.grid().tree().evalLeafBoundingBox(box);
    return box;
}

TEST(SurfaceRay, AgreesWithOpenVdbsIntersectorOnASphereAndATorus)
{
    std::mt19937 random(20261204);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const FieldImage shapes[] = {makeSphere(20.0, 0.5), makeTorus(18.0, 6.0, 0.5)};
    double worstApart = 0.0, worstOurs = 0.0, worstTheirs = 0.0;  // voxels
    for (const FieldImage& field : shapes) {
        openvdb::tools::LevelSetRayIntersector<openvdb::FloatGrid> reference(field.grid());
        const openvdb::CoordBBox box = leafBox(field);
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            openvdb::Vec3d eye(unit(random), unit(random), unit(random));
            eye = eye.unit() * 70.0;
            const openvdb::Vec3d aim = openvdb::Vec3d(unit(random), unit(random), unit(random)) * 22.0;
            const openvdb::Vec3d direction = (aim - eye).unit();
            openvdb::Vec3d expected, normal;
            const bool hit = reference.intersectsWS(openvdb::math::Ray<double>(eye, direction), expected, normal);
            const auto crossing = firstSurfaceCrossing(PreEditField(field, nullptr), box, eye, direction);
            ASSERT_EQ(crossing.has_value(), hit) << "ray " << i;
            if (!hit) continue;
            ++hits;
            worstApart = std::max(worstApart, (crossing->position - expected).length() / field.voxelSize());
            if (&field == &shapes[0]) {  // the sphere: against its radius
                worstOurs = std::max(worstOurs, std::abs(crossing->position.length() - 20.0) / field.voxelSize());
                worstTheirs = std::max(worstTheirs, std::abs(expected.length() - 20.0) / field.voxelSize());
            }
            EXPECT_GT(crossing->normal.dot(normal.unit()), 0.999) << "ray " << i;
        }
        EXPECT_GT(hits, 100);
    }
    // OpenVDB's linear search interpolates along the ray between voxel steps; ours bisects the
    // trilinear field, so it lies closer to the analytic sphere (0.006 voxel against 0.015 here).
    EXPECT_LT(worstApart, 0.2);
    EXPECT_LT(worstOurs, 0.02);
    EXPECT_LE(worstOurs, worstTheirs);
}

TEST(SurfaceRay, FromInsideItFindsWhereTheRayLeavesAndAMissIsAMiss)
{
    const FieldImage field = makeSphere(20.0, 0.5);
    const auto exit = firstSurfaceCrossing(PreEditField(field, nullptr), leafBox(field), {0, 0, 0}, {0, 0, 3});
    ASSERT_TRUE(exit);
    EXPECT_NEAR(exit->position.z(), 20.0, 0.05 * 0.5);
    EXPECT_GT(exit->normal.z(), 0.999);  // outwards
    EXPECT_FALSE(firstSurfaceCrossing(PreEditField(field, nullptr), leafBox(field), {0, 30, -60}, {0, 0, 1}));
    EXPECT_FALSE(firstSurfaceCrossing(PreEditField(field, nullptr), leafBox(field), {0, 0, 60}, {0, 0, 1}));
}

TEST(SurfaceRay, ThroughAStrokesJournalTheRaySeesTheSurfaceAsItWasBeforeTheStroke)
{
    FieldImage field = makeSphere(20.0, 0.5);
    const openvdb::CoordBBox box = leafBox(field);
    const openvdb::Vec3d eye(0, 0, 80), down(0, 0, -1);
    const auto before = firstSurfaceCrossing(PreEditField(field, nullptr), box, eye, down);
    ASSERT_TRUE(before);
    BrushSettings add;
    add.radiusWorld = 5.0;
    add.strength = 1.0;
    LeafJournal journal;
    for (int i = 0; i < 5; ++i) applyStamp(field, add, {before->position, before->position, 1.0, down}, &journal);
    ASSERT_GT(journal.leafCount(), 0u);
    const auto live = firstSurfaceCrossing(PreEditField(field, nullptr), leafBox(field), eye, down);
    ASSERT_TRUE(live);
    EXPECT_GT(live->position.z(), before->position.z() + 1.0);  // the clay the stamps added
    const auto frozen = firstSurfaceCrossing(PreEditField(field, &journal), box, eye, down);
    ASSERT_TRUE(frozen);
    EXPECT_EQ(frozen->position, before->position);  // the same values read: the same hit, bit for bit
    EXPECT_EQ(frozen->normal, before->normal);
}

}  // namespace
}  // namespace sculpt
