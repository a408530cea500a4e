// SPDX-License-Identifier: Apache-2.0
#include "ui/tools/sculpt/sculpt_tool.h"

#include "core/base/errors.h"
#include "sculpt/session/document.h"
#include "ui/commands/command_registry.h"
#include "ui/input/input_event.h"
#include "ui/tools/tool_box.h"
#include "ui/tools/tool_host.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace sculpt::ui {

namespace {

struct BrushToolRow {
    Command command;
    BrushTool tool;
    const char* label;
    const char* help;
    int key;
};

// Blender's sculpt-mode keys where it has one.
const BrushToolRow kBrushTools[] = {
    {Command::ToolAdd, BrushTool::Add, "Add", "Builds clay up (Ctrl: carve)", GLFW_KEY_A},
    {Command::ToolCarve, BrushTool::Carve, "Carve", "Digs clay away (Ctrl: add)", GLFW_KEY_C},
    {Command::ToolInflate, BrushTool::Inflate, "Inflate", "Swells the surface along its normal (Ctrl: deflate)",
     GLFW_KEY_I},
    {Command::ToolDeflate, BrushTool::Deflate, "Deflate", "Shrinks the surface along its normal (Ctrl: inflate)",
     GLFW_KEY_D},
    {Command::ToolSmooth, BrushTool::Smooth, "Smooth", "Evens out bumps (hold Shift with any tool)", GLFW_KEY_S},
    {Command::ToolFlatten, BrushTool::Flatten, "Flatten", "Presses the surface onto its mean plane", GLFW_KEY_T},
    {Command::ToolGrab, BrushTool::Grab, "Grab", "Drags the clay under the brush along with the mouse", GLFW_KEY_G},
    {Command::ToolPinch, BrushTool::Pinch, "Pinch", "Pulls the surface towards the stroke: sharp creases", GLFW_KEY_P},
    {Command::ToolFollow, BrushTool::Follow, "Follow",
     "Pulls the surface under the brush onto the target shape (Ctrl+T loads one)", GLFW_KEY_O},
    {Command::ToolPrimitive, BrushTool::Primitive, "Blob", "Stamps a soft blob (Ctrl: carves one)", GLFW_KEY_B},
    {Command::ToolMask, BrushTool::Mask, "Mask",
     "Paints the mask: masked clay holds still under every tool, filter and morph (Ctrl: erases it)", GLFW_KEY_M},
};

}  // namespace

void SculptTool::addCommands(CommandRegistry& registry, ToolBox& box)
{
    for (const BrushToolRow& row : kBrushTools) {
        registry.add({row.command, row.label, row.help, {{row.key}}, {}, [this, &box, tool = row.tool] {
                          mHost.brush().tool = tool;
                          box.choose(*this);
                          if (tool == BrushTool::Follow && !mHost.brush().target.shape)
                              mHost.notify("the follow brush needs a target: File > Load Target (Ctrl+T)");
                      }});
    }
    registry.add({Command::RadiusSmaller, "Smaller brush", "Radius x 0.8", {{GLFW_KEY_LEFT_BRACKET}}, {}, [this] {
                      BrushOptions& brush = mHost.brush();
                      brush.radius = std::max(0.5 * mHost.document().session().field().voxelSize(), brush.radius * 0.8);
                  }});
    registry.add({Command::RadiusLarger, "Larger brush", "Radius x 1.25", {{GLFW_KEY_RIGHT_BRACKET}}, {}, [this] {
                      mHost.brush().radius *= 1.25;
                  }});
    const struct {
        Command command;
        const char* label;
        const char* help;
        int key;
        bool Symmetry::*axis;
    } mirrors[] = {{Command::SymmetryX, "Mirror X", "Mirror strokes across the plane x = 0", GLFW_KEY_X, &Symmetry::x},
                   {Command::SymmetryY, "Mirror Y", "Mirror strokes across the plane y = 0", GLFW_KEY_Y, &Symmetry::y},
                   {Command::SymmetryZ, "Mirror Z", "Mirror strokes across the plane z = 0", GLFW_KEY_Z, &Symmetry::z}};
    for (const auto& mirror : mirrors) {
        registry.add({mirror.command, mirror.label, mirror.help, {{mirror.key}}, {}, [this, axis = mirror.axis] {
                          bool& on = mHost.brush().symmetry.*axis;
                          on = !on;
                      }});
    }
}

bool SculptTool::press(const InputEvent& event)
{
    if (mStroke.active()) return true;      // another button during a stroke: it goes on
    const glm::dvec2 at = mHost.pointer();  // a button event has no position
    const std::optional<SurfaceHit> hit = mHost.pickAt(at.x, at.y);
    if (!hit || mHost.busy()) return false;
    Document& document = mHost.document();
    try {
        mHost.picker().freeze(document.session().field(), document.session().mesher()->version());
        mStrokeMods = event.mods | mHost.heldMods();
        mStroke.begin(document, mHost.brush(), mStrokeMods, *hit, mHost.viewport().rayThrough(at.x, at.y), event.time,
                      at.x, at.y);
        mHost.awaitFrame(0);
    } catch (const InputError& e) {
        mHost.picker().thaw();
        mHost.showError(e.what());
    }
    return true;
}

void SculptTool::drag(const InputEvent& event)
{
    const std::optional<SurfaceHit> hit = mHost.pickAt(event.x, event.y);
    try {
        const std::size_t stamps = mStroke.move(mHost.document(), hit, mHost.viewport().rayThrough(event.x, event.y),
                                                event.time, event.x, event.y);
        // From when the pointer got there (a replayed event: when it was due) to the frame showing it.
        if (stamps > 0) mHost.awaitFrame(stamps);
    } catch (const InputError& e) {
        mHost.showError(e.what());
    }
}

void SculptTool::release(const InputEvent& event)
{
    if (event.button == kLeftButton) finish();
}

void SculptTool::finish()
{
    if (!mStroke.active()) return;
    mStroke.end(mHost.document());
    mHost.picker().thaw();
}

BrushTool SculptTool::toolUnder(int mods) const
{
    return effectiveTool(mHost.brush().tool, mStroke.active() ? mStrokeMods : mods);
}

}  // namespace sculpt::ui
