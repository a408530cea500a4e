// SPDX-License-Identifier: Apache-2.0
// MorphMode's panel: the frames' slider, play/pause, step, keep, export, close; the tracked
// mesh's quality; how the morph ended.

#include "core/motion/morph_verdict.h"
#include "ui/modes/morph_mode.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

namespace sculpt::ui {

namespace {

/// The tracked mesh's line: the shown frame's quality, and the wireframe's switch.
void trackedMeshLine(MorphFrames& frames, WireDisplay& wire)
{
    const MorphTracking& tracking = *frames.run().tracking;
    const TrackedFrame& f = tracking.frames().at(std::size_t(frames.shown()));
    bool shown = wire.shown();
    if (ImGui::Checkbox("tracked mesh", &shown)) wire.setShown(shown);
    ImGui::SameLine();
    const double e = tracking.edgeLength();
    // A segment holds every vertex its frames have had (tracked_sequence.h); the quality is this frame's.
    const std::vector<TrackedSegment>& segments = tracking.sequence().segments();
    ImGui::TextDisabled("segment %zu of %zu, %zu vertices; this frame %zu, smallest angle %.1f deg, edges %.2f-%.2f e, "
                        "%zu flagged",
                        f.segment + 1, segments.size(), segments.at(f.segment).ids.size(), f.quality.vertices,
                        f.quality.smallestAngle, f.quality.shortestEdge / e, f.quality.longestEdge / e, f.flagged);
}

}  // namespace

void MorphMode::drawPanel(PanelHost& host)
{
    MorphFrames& frames = mFrames;
    beginBottomPanel("Morph", true);
    int shown = frames.shown();
    ImGui::SetNextItemWidth(360.f);
    if (ImGui::SliderInt("frame", &shown, 0, frames.count() - 1)) frames.show(shown);
    const auto button = [&host](const char* label, Command command) {
        if (ImGui::Button(label)) host.execute(command);
        commandTooltip(host, command);
        ImGui::SameLine();
    };
    button("<", Command::StepUp);
    button(frames.playing() ? "Pause" : "Play", Command::MorphPlay);
    button(">", Command::StepDown);
    button("Keep frame", Command::MorphKeep);
    button("Export frames...", Command::MorphExport);
    if (ImGui::Button("Close (Esc)")) host.execute(Command::Cancel);
    if (frames.run().tracking) trackedMeshLine(frames, mWire);
    const MorphSummary& s = frames.run().summary;
    const std::string verdict = morphVerdict(s, frames.shownField().voxelSize());
    ImGui::PushTextWrapPos(560.f);
    ImGui::TextDisabled("%d steps, final distance %.3g: %s", s.steps, s.finalDistanceWorld, verdict.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace sculpt::ui
