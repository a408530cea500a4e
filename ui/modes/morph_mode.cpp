#include "ui/modes/morph_mode.h"

#include "core/field/grid_checksum.h"
#include "core/motion/morph_verdict.h"
#include "sculpt/session/document.h"
#include "ui/modes/mode_host.h"
#include "ui/panels/panels.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

MorphMode::MorphMode(vtkRenderer* scene, std::string label, MorphRun run)
    : mLabel(std::move(label)), mFrames(std::move(run)), mWire(scene)
{}

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
    const std::optional<MorphTracking>& tracking = mFrames.run().tracking;
    if (!tracking || mWireFrame == mFrames.shown()) return false;
    mWireFrame = mFrames.shown();
    const TriangleMesh mesh = tracking->frameMesh(mWireFrame);
    mWire.set(&mesh);
    return true;
}

bool MorphMode::accept(ModeHost& host)
{
    const std::string frame = std::to_string(mFrames.shown());
    host.document().replaceField(mFrames.shownField().deepCopy(), "morph frame " + frame);
    host.notify("kept morph frame " + frame + " (Ctrl+Z undoes it)");
    return true;
}

void MorphMode::drawPanel(SculptApp& app) { drawMorphPanel(app, *this); }

nlohmann::json MorphMode::report()
{
    nlohmann::json report{{"frames", mFrames.count()},
                          {"shown", mFrames.shown()},
                          {"checksum", formatChecksum(gridChecksum(mFrames.shownField().grid()))},
                          {"converged", mFrames.run().summary.converged},
                          {"stop", morphStopName(mFrames.run().summary.stop)}};
    const std::optional<MorphTracking>& tracking = mFrames.run().tracking;
    if (!tracking) return report;
    nlohmann::json frames = nlohmann::json::array();
    for (const TrackedFrame& f : tracking->frames())
        frames.push_back({{"vertices", f.quality.vertices},
                          {"triangles", f.quality.triangles},
                          {"segment", f.segment},
                          {"smallest_angle", f.quality.smallestAngle},
                          {"shortest_edge_e", f.quality.shortestEdge / tracking->edgeLength()},
                          {"longest_edge_e", f.quality.longestEdge / tracking->edgeLength()},
                          {"flagged", f.flagged}});
    report["tracked"] = {{"frames", frames},
                         {"segments", tracking->sequence().segments().size()},
                         {"wire_shown", mWire.shown()},
                         {"wire_frame", mWireFrame}};
    return report;
}

}  // namespace sculpt::ui
