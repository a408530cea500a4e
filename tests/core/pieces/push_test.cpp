// SPDX-License-Identifier: Apache-2.0
#include "core/field/grid_checksum.h"
#include "core/mesh/field_measures.h"
#include "core/pieces/push.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <tbb/global_control.h>

#include <vector>

namespace sculpt {
namespace {

openvdb::Mat4d movedTo(const openvdb::Vec3d& offset)
{
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    m.setTranslation(offset);
    return m;
}

/// Voxels inside the pusher (its own lattice, placed) that are inside the pushed piece too.
std::size_t pusherVoxelsInside(const FieldImage& pusher, const openvdb::Mat4d& placement, const FieldImage& pushed)
{
    const auto accessor = pushed.grid().getConstAccessor();
    std::size_t inside = 0;
    for (auto v = pusher.grid().cbeginValueOn(); v; ++v) {
        if (*v >= 0.0f) continue;
        const openvdb::Vec3d world = placement.transform(pusher.grid().indexToWorld(v.getCoord()));
        inside += openvdb::tools::BoxSampler::sample(accessor, pushed.grid().worldToIndex(world)) < 0.0;
    }
    return inside;
}

}  // namespace

// A ball of radius 6 pushed 2 deep into a ball of radius 10 dents it: the dented ball keeps its
// volume within 0.5%, stays one shell, and no voxel inside the pusher is inside it.
TEST(Push, TheDentedPieceKeepsItsVolumeAndLeavesThePusherFree)
{
    FieldImage ball = makeSphere(10.0, 0.5);
    const FieldImage pusher = makeSphere(6.0, 0.5);
    const openvdb::Mat4d placement = movedTo(openvdb::Vec3d(14.0, 0.0, 0.0));
    const double before = measureField(ball).volume;
    ASSERT_GT(pusherVoxelsInside(pusher, placement, ball), 100u);
    const PushReport report = pushAside(ball, openvdb::Mat4d::identity(), pusher, placement);
    const FieldMeasures after = measureField(ball);
    EXPECT_NEAR(after.volume, before, 0.005 * before);
    EXPECT_GT(report.dent, 0.01 * before) << "the cut alone removes a visible volume";
    EXPECT_EQ(after.components, 1);
    EXPECT_EQ(after.eulerCharacteristic, 2);
    EXPECT_EQ(pusherVoxelsInside(pusher, placement, ball), 0u);
}

// Apart, nothing changes, bit for bit.
TEST(Push, PiecesApartAreLeftAsTheyWere)
{
    FieldImage ball = makeSphere(10.0, 0.5);
    const auto before = gridChecksum(ball.grid());
    const PushReport report =
        pushAside(ball, openvdb::Mat4d::identity(), makeSphere(6.0, 0.5), movedTo(openvdb::Vec3d(17.0, 0.0, 0.0)));
    EXPECT_EQ(report.dent, 0.0);
    EXPECT_EQ(gridChecksum(ball.grid()), before);
}

// A small piece on a finer lattice (an eye, voxels of 0.25) pushed 2 deep by a body (0.5):
// the same dent bit for bit run after run and on one or two threads (a replay of a push must
// give the window's grid), its volume kept and still one shell.
TEST(Push, APushIsBitIdenticalRunToRunAndOnOneOrTwoThreads)
{
    const FieldImage body = makeSphere(10.0, 0.5), eye = makeSphere(3.0, 0.25);
    const openvdb::Mat4d eyePlacement = movedTo(openvdb::Vec3d(20.0, 0.0, 0.0)),
                         bodyPlacement = movedTo(openvdb::Vec3d(8.0, 0.0, 0.0));
    std::vector<std::uint64_t> dents;
    for (const int threads : {2, 2, 1, 2}) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
        FieldImage pushed = eye.deepCopy();
        const PushReport report = pushAside(pushed, eyePlacement, body, bodyPlacement);
        EXPECT_GT(report.dent, 0.0);
        EXPECT_NEAR(report.volumeAfter, report.volumeBefore, 0.01 * report.volumeBefore);
        dents.push_back(gridChecksum(pushed.grid()));
    }
    for (std::size_t i = 1; i < dents.size(); ++i) EXPECT_EQ(dents[i], dents[0]) << "run " << i;
    EXPECT_NE(dents[0], gridChecksum(eye.grid()));
}

}  // namespace sculpt
