// The model display on a renderer that never draws: what it uploads when the mesher it shows
// is replaced.

#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"
#include "ui/view/model_display.h"
#include "ui/view/surface_look.h"

#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <new>

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
