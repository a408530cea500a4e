// SPDX-License-Identifier: Apache-2.0
#include "core/base/text_format.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

namespace sculpt::ui {

void drawStatusBar(PanelHost& host)
{
    const ImGuiIO& io = ImGui::GetIO();
    const float height = ImGui::GetFrameHeight() + 6.f;
    ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height), ImGuiCond_Always);
    ImGui::Begin("Status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    const StatusFigures& s = host.status();
    const std::string& units = host.document().session().field().units();
    if (s.pieces > 1) {  // the figures after it are the sculpted piece's
        ImGui::Text("%s, one of %zu pieces (all shown: %s tris) |", s.piece.c_str(), s.pieces,
                    formatCount(s.allTriangles).c_str());
        ImGui::SameLine();
    }
    ImGui::Text(
        "%.0f ms | %s tris | %s voxels | mem %s | undo %s | volume %s %s3 | area %s %s2 | Euler %lld | shells %zu",
        s.frameMs, formatCount(s.triangles).c_str(), formatCount(s.activeVoxels).c_str(),
        formatBytes(double(s.memoryBytes)).c_str(), formatBytes(double(s.undoBytes)).c_str(),
        formatNumber(s.volume).c_str(), units.c_str(), formatNumber(s.area).c_str(), units.c_str(), s.euler, s.shells);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("memory %s: grid %s, surface mesh %s, display %s (the GL driver holds as much again), "
                          "undo %s, the rest libraries and the window",
                          formatBytes(double(s.memoryBytes)).c_str(), formatBytes(double(s.gridBytes)).c_str(),
                          formatBytes(double(s.mesherBytes)).c_str(), formatBytes(double(s.displayBytes)).c_str(),
                          formatBytes(double(s.undoBytes)).c_str());
    }
    if (!host.notices().notice().empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("| %s", host.notices().notice().c_str());
    }
    ImGui::End();
}

}  // namespace sculpt::ui
