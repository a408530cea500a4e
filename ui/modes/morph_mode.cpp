// SPDX-License-Identifier: Apache-2.0
#include "ui/modes/morph_mode.h"

#include "core/field/grid_checksum.h"
#include "core/motion/morph_verdict.h"
#include "sculpt/session/document.h"
#include "sculpt/session/frame_files.h"
#include "sculpt/session/morph_run.h"
#include "sculpt/session/tracked_export.h"
#include "ui/input/input_event.h"
#include "ui/modes/mode_slot.h"
#include "ui/panels/panel_host.h"

#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

/// Morphs a copy of the model into the file at `target` as a job; its frames open in `slot`.
void startMorph(ModeSlot& slot, const fs::path& target, const MorphOptions& options, bool tracked)
{
    Workspace& work = slot.host().workspace();
    if (work.busy()) return;
    work.autosaveNow();
    auto copy = std::make_shared<FieldImage>(work.document().session().field().deepCopy());
    const std::string label = "morph to " + target.filename().string();
    work.startJob<MorphRun>(
        label,
        [copy, target, options, tracked](const Progress& p) { return morphInto(*copy, target, options, p, tracked); },
        [&slot, label, target](MorphRun run) {
            // The target becomes the loaded one: its ghost shows where the frames go.
            PanelHost& host = slot.host();
            host.brush().target = {target, run.target};
            host.view().ghost().set(run.target.get());
            slot.open(std::make_unique<MorphMode>(host.view().viewport().renderer(), label, std::move(run)));
        });
}

/// Writes the frames of `morph` (and its tracked mesh) into the directory `path`.
void exportFrames(MorphMode& morph, const fs::path& path, Notices& notices)
{
    const MorphRun& run = morph.frames().run();
    WrittenOutputs outputs;  // an export that fails leaves no frames behind
    writeFrames(run.frames, path, outputs);
    std::string notice = "wrote " + std::to_string(morph.frames().count()) + " frames to " + path.string();
    if (run.tracking) {
        writeTrackedSequence(run.tracking->sequence(), path / "tracked");
        notice += " and the tracked mesh (" + std::to_string(run.tracking->sequence().segments().size()) +
                  " segments: .ply, .pc2, .glb, .usda) to " + (path / "tracked").string();
    }
    outputs.keep();
    notices.say(notice);
}

}  // namespace

void MorphMode::addCommands(CommandRegistry& commands, ModeSlot& slot)
{
    PanelHost& host = slot.host();
    Dialogs& dialogs = host.dialogs();
    const auto morphing = [&slot] {
        return slot.as<MorphMode>() ? std::string()
                                    : std::string("no morph frames on show: Filters > Morph To makes them");
    };
    commands.add({Command::MorphTo,
                  "Morph To...",
                  "Morph the model into a target document, scan or mesh, as a job; then play and keep frames",
                  {{GLFW_KEY_M, kAlt}},
                  [&host] { return host.workspace().waitReason(); },
                  [&slot, &host, &dialogs] {
                      dialogs.ask(Prompt::Kind::Morph, host.brush().target.path.string(),
                                  [&slot, &dialogs](const fs::path& target) {
                                      startMorph(slot, target, dialogs.morph, dialogs.morphTracked);
                                  });
                  }});
    commands.add({Command::MorphPlay,
                  "Play/Pause Morph",
                  "Play the morph's frames (Morph panel)",
                  {{GLFW_KEY_SPACE}},
                  morphing,
                  [&slot, &host] { slot.as<MorphMode>()->frames().togglePlay(host.time()); }});
    commands.add({Command::MorphKeep,
                  "Keep Frame",
                  "Make the frame shown the document (one undo step)",
                  {{GLFW_KEY_K}},
                  morphing,
                  [&slot] { slot.accept(); }});
    commands.add({Command::MorphExport,
                  "Export Frames...",
                  "Write the morph's frames as DIR/frame_0000.vdb ...",
                  {{GLFW_KEY_E, kShift}},
                  morphing,
                  [&slot, &dialogs] {
                      dialogs.ask(Prompt::Kind::MorphExport, "morph", [&slot](const fs::path& path) {
                          if (MorphMode* morph = slot.as<MorphMode>())
                              exportFrames(*morph, path, slot.host().notices());
                      });
                  }});
}

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

bool MorphMode::accept(PanelHost& host)
{
    const std::string frame = std::to_string(mFrames.shown());
    host.document().replaceField(mFrames.shownField().deepCopy(), "morph frame " + frame);
    host.workspace().landed("keep morph frame " + frame);
    return true;
}

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
