// SPDX-License-Identifier: Apache-2.0
// The model display on a renderer that never draws: what it uploads when the mesher it shows is
// replaced or a stamp changes it, and what its level of detail draws.

#include "core/brushes/brush.h"
#include "core/mesh/incremental_mesher.h"
#include "core/mesh/preview_mesh.h"
#include "core/primitives/analytic_shapes.h"
#include "ui/view/block_cluster.h"
#include "ui/view/model_display.h"
#include "ui/view/surface_look.h"

#include <gtest/gtest.h>
#include <vtkActorCollection.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <set>

using namespace sculpt;
using namespace sculpt::ui;

TEST(ModelDisplay, AMesherMadeWhereAFreedOneLivedIsUploadedWhole)
{
    vtkNew<vtkRenderer> renderer;
    SurfaceLook look;
    ModelDisplay display(renderer, look);
    const FieldImage ball = makeSphere(10.0, 0.5), box = makeBox(14.0, 0.5);
    // Two morph frames shown one after the other: the second mesher takes the first one's
    // storage, and both are at version 1, so only an identity tells them apart.
    alignas(IncrementalMesher) unsigned char storage[sizeof(IncrementalMesher)];
    auto* first = new (storage) IncrementalMesher();
    first->rebuild(ball);
    display.sync(*first, 0.5);
    const std::uint64_t version = first->version();
    ASSERT_EQ(display.blockCount(), first->blocks().size());
    first->~IncrementalMesher();
    auto* second = new (storage) IncrementalMesher();
    second->rebuild(box);
    ASSERT_EQ(second->version(), version);
    display.sync(*second, 0.5);
    EXPECT_EQ(display.blockCount(), second->blocks().size());
    EXPECT_EQ(display.lastUploads(), second->blocks().size()) << "the old frame's blocks stayed on screen";
    second->~IncrementalMesher();
}

// The coarse twins drawn while the camera moves: far fewer triangles, none degenerate, and every
// vertex still on the surface to within a cluster cell.
TEST(ModelDisplay, ClusteredBlocksKeepTheSurfaceWithinACellWithAFractionOfItsTriangles)
{
    const double radius = 20.0, voxel = 0.5, cell = 3.0 * voxel;
    IncrementalMesher mesher;
    mesher.rebuild(makeSphere(radius, voxel));
    std::size_t full = 0, coarse = 0;
    double worst = 0.0;
    for (const auto& [origin, mesh] : mesher.blocks()) {
        const BlockMesh clustered = clusterBlockMesh(mesh, cell);
        full += mesh.triangles.size();
        coarse += clustered.triangles.size();
        for (const auto& t : clustered.triangles) {
            EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) << "a degenerate triangle";
        }
        for (const auto& p : clustered.positions) {
            const double r = std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]);
            worst = std::max(worst, std::abs(r - radius));
        }
    }
    ASSERT_GT(full, 10000u);
    EXPECT_LT(double(coarse), double(full) / 4.0) << coarse << " of " << full;  // (cell / voxel)^2 = 9
    EXPECT_GT(coarse, 0u);
    EXPECT_LT(worst, cell * std::sqrt(3.0) / 2.0) << "a vertex left the surface by more than half a cell diagonal";
}

// Issue 31: one actor per block made VTK's bookkeeping and Mesa's per-draw cost grow with the
// model. Chunks keep the actors bounded, and a far view draws the coarse twins.
TEST(ModelDisplay, ActorsStayBoundedAndAMovingViewDrawsWithinItsBudgetWhileAStillOneDrawsAll)
{
    vtkNew<vtkRenderer> renderer;
    SurfaceLook look;
    ModelDisplay display(renderer, look);
    IncrementalMesher mesher(8);  // small blocks: over 10,000 of them on a ball of radius 200
    mesher.rebuild(makeSphere(200.0, 1.0));
    ASSERT_GT(mesher.blocks().size(), 10000u);
    display.sync(mesher, 1.0);
    EXPECT_LE(display.chunkCount(), ModelDisplay::kMaxChunks);
    EXPECT_EQ(display.actorCount(), display.chunkCount());  // no twin back yet: a frame never waits
    EXPECT_EQ(std::size_t(renderer->GetActors()->GetNumberOfItems()), display.actorCount());
    EXPECT_EQ(display.trianglesDrawn(), mesher.triangleCount());
    display.finishTwins(1.0);  // the worker has clustered every chunk
    EXPECT_EQ(display.actorCount(), 2 * display.chunkCount());

    DetailView far;  // moving, the model a few hundred pixels across: 2 voxels a pixel
    far.still = false;
    far.eye = glm::dvec3(0.0, 0.0, 5000.0);
    far.pixelSizeAt = [](const glm::dvec3&) { return 2.0; };
    const std::size_t pixels = 1280 * 800;
    ASSERT_GT(mesher.triangleCount(), pixels);
    display.sync(mesher, 1.0, far);
    EXPECT_EQ(display.coarseChunks(), display.chunkCount());
    EXPECT_LT(display.trianglesDrawn(), pixels / 4);
    EXPECT_LE(display.actorCount(), 2 * ModelDisplay::kMaxChunks);

    DetailView near = far;  // voxels of four pixels, but more triangles than the window has pixels
    near.pixelSizeAt = [](const glm::dvec3&) { return 0.25; };
    near.triangleBudget = mesher.triangleCount() / 2;
    display.sync(mesher, 1.0, near);
    EXPECT_GT(display.coarseChunks(), 0u);
    EXPECT_LT(display.coarseChunks(), display.chunkCount());
    EXPECT_LE(display.trianglesDrawn(), near.triangleBudget);

    display.sync(mesher, 1.0, DetailView{});  // the camera rests: full detail everywhere
    EXPECT_EQ(display.coarseChunks(), 0u);
    EXPECT_EQ(display.trianglesDrawn(), mesher.triangleCount());
}

// Issue 31: a stamp on a model of over 10,000 blocks re-uploads the chunks holding the blocks the
// mesher changed, and those lie within the brush's reach: nothing else of the model is touched.
TEST(ModelDisplay, AStampOnAModelOfOver10000BlocksReuploadsOnlyTheChunksWithinItsReach)
{
    vtkNew<vtkRenderer> renderer;
    SurfaceLook look;
    ModelDisplay display(renderer, look);
    FieldImage ball = makeSphere(200.0, 1.0);
    IncrementalMesher mesher(8);
    mesher.rebuild(ball);
    ASSERT_GT(mesher.blocks().size(), 10000u);
    display.sync(mesher, 1.0);

    BrushSettings brush;
    brush.radiusWorld = 6.0;
    BrushStamp stamp;
    stamp.centreWorld = stamp.previousWorld = openvdb::Vec3d(200.0, 0.0, 0.0);
    const std::uint64_t before = mesher.version();
    ASSERT_GT(mesher.update(ball, applyStamp(ball, brush, stamp, nullptr)), 0u);
    const IncrementalMesher::Changes changes = mesher.changesSince(before);
    display.sync(mesher, 1.0);

    const int size = display.chunkBlocks() * mesher.blockVoxels();
    std::set<openvdb::Coord> reached;
    for (const auto* list : {&changes.updated, &changes.removed}) {
        for (const openvdb::Coord& b : *list)
            reached.insert({floorToMultiple(b.x(), size), floorToMultiple(b.y(), size), floorToMultiple(b.z(), size)});
    }
    EXPECT_EQ(display.lastUploads(), changes.updated.size());
    EXPECT_EQ(display.lastChunkUploads(), reached.size());
    EXPECT_LT(reached.size(), display.chunkCount()) << "the whole model was re-uploaded";
    // A block is re-meshed when its cells or normals read a dirty leaf, and a leaf is dirty when
    // the stamp's radius plus the band reaches it: a leaf and a block beyond radius + band.
    const double reach = brush.radiusWorld + 3.0 + 8.0 + 8.0 + 1.0;
    for (const openvdb::Coord& origin : reached) {
        const glm::dvec3 lo(origin.x(), origin.y(), origin.z()), centre(200.0, 0.0, 0.0);
        const glm::dvec3 nearest = glm::clamp(centre, lo, lo + glm::dvec3(size));
        EXPECT_LE(glm::length(nearest - centre), reach) << "a chunk at " << origin << " is out of the brush's reach";
    }
}

// Issue 31, item 5: opening a large model shows its preview at once, then fills in full detail
// within the budget a sync, each chunk drawing its part of the preview until its own upload.
TEST(ModelDisplay, APreviewStandsInUntilEveryChunkHasFilledInWithinTheBudget)
{
    vtkNew<vtkRenderer> renderer;
    SurfaceLook look;
    ModelDisplay display(renderer, look);
    const FieldImage ball = makeSphere(120.0, 1.0);
    IncrementalMesher before(16), opened(16);
    before.rebuild(makeSphere(30.0, 1.0));
    display.sync(before, 1.0);
    const TriangleMesh preview = previewMesh(ball, 4);

    display.showPreview(preview, ball.grid().transform());
    display.sync(before, 1.0);  // the old model's mesher: the preview alone is shown
    EXPECT_TRUE(display.showsPreview());
    EXPECT_EQ(display.chunkCount(), 0u);
    EXPECT_EQ(std::size_t(renderer->GetActors()->GetNumberOfItems()), 1u);
    EXPECT_EQ(display.trianglesDrawn(), preview.triangles.size());

    opened.rebuild(ball);
    display.setFillBudget(opened.triangleCount() / 5);
    display.sync(opened, 1.0);
    EXPECT_FALSE(display.showsPreview());
    EXPECT_GT(display.pendingChunks(), 0u);
    EXPECT_LE(display.lastUploadBytes(), display.meshBytes());
    int syncs = 1;
    for (std::size_t pending = display.pendingChunks(); pending > 0; pending = display.pendingChunks(), ++syncs) {
        // Each sync fills in at most the budget and a chunk more; the rest draw their preview.
        EXPECT_LT(display.trianglesDrawn(), opened.triangleCount() + preview.triangles.size());
        EXPECT_EQ(display.coarseChunks(), pending);
        display.sync(opened, 1.0);
        EXPECT_LT(display.pendingChunks(), pending);
        ASSERT_LT(syncs, 20);
    }
    EXPECT_GE(syncs, 5);  // a fifth of the model a sync
    EXPECT_LE(syncs, 8);
    EXPECT_EQ(display.coarseChunks(), 0u);
    EXPECT_EQ(display.trianglesDrawn(), opened.triangleCount());  // still: full detail everywhere

    display.showPreview(preview, ball.grid().transform());  // an open that fails:
    display.dropPreview();
    display.sync(opened, 1.0);  // the model shown before comes back whole
    EXPECT_EQ(display.trianglesDrawn(), opened.triangleCount());
    EXPECT_EQ(display.pendingChunks(), 0u);
}
