#include "ui/modes/morph_mode.h"

#include "core/field/grid_checksum.h"
#include "core/motion/morph_verdict.h"
#include "ui/document/document.h"
#include "ui/modes/mode_host.h"
#include "ui/panels/panels.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

std::string MorphMode::waitNotice() const
{
    return "the morph's frames are on show: keep one (K) or close them (Esc) first";
}

std::string MorphMode::hint() const
{
    const MorphSummary& s = mFrames.run().summary;
    return mLabel + ": " + std::to_string(mFrames.count()) + " frames, " +
           (s.converged ? "converged" : std::string("NOT converged (") + morphStopName(s.stop) + ")") +
           " (Space plays, K keeps a frame)";
}

bool MorphMode::sync(double now)
{
    mFrames.tick(now);
    return false;
}

bool MorphMode::accept(ModeHost& host)
{
    const std::string frame = std::to_string(mFrames.shown());
    host.document().replaceField(mFrames.shownField().deepCopy(), "morph frame " + frame);
    host.notify("kept morph frame " + frame + " (Ctrl+Z undoes it)");
    return true;
}

void MorphMode::drawPanel(SculptApp& app) { drawMorphPanel(app, mFrames); }

nlohmann::json MorphMode::report()
{
    return {{"frames", mFrames.count()},
            {"shown", mFrames.shown()},
            {"checksum", formatChecksum(gridChecksum(mFrames.shownField().grid()))},
            {"converged", mFrames.run().summary.converged},
            {"stop", morphStopName(mFrames.run().summary.stop)}};
}

}  // namespace sculpt::ui
