#include "ui/tools/sculpt/sculpt_tool.h"

#include "core/base/errors.h"
#include "ui/document/document.h"
#include "ui/input/input_event.h"
#include "ui/tools/tool_host.h"

namespace sculpt::ui {

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
        mHost.awaitFrame(event, 0);
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
        if (stamps > 0) mHost.awaitFrame(event, stamps);
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
