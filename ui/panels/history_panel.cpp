// SPDX-License-Identifier: Apache-2.0
#include "core/base/text_format.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

namespace sculpt::ui {

void drawHistoryPanel(PanelHost& host)
{
    const ImVec2 size(236, 260);
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - size.x - 8, 28), ImGuiCond_Always);
    ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    ImGui::Begin("History", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    const Document& doc = host.document();
    std::size_t bytes = 0, forgotten = 0;
    for (const DocumentPiece& piece : doc.pieces()) {
        bytes += piece.session->history().memoryBytes();
        forgotten += piece.session->history().droppedCount();
    }
    ImGui::Text("%zu undo, %zu redo, %s", doc.undoLabels().size(), doc.redoLabels().size(),
                formatBytes(double(bytes)).c_str());
    if (forgotten > 0) ImGui::TextDisabled("%zu oldest forgotten (memory budget)", forgotten);
    if (ImGui::Button("Undo")) host.execute(Command::Undo);
    commandTooltip(host, Command::Undo);
    ImGui::SameLine();
    if (ImGui::Button("Redo")) host.execute(Command::Redo);
    commandTooltip(host, Command::Redo);
    ImGui::Separator();
    ImGui::BeginChild("strokes");
    ImGui::TextDisabled("(opened)");
    for (const std::string& label : doc.undoLabels()) ImGui::TextUnformatted(label.c_str());
    for (const std::string& label : doc.redoLabels()) ImGui::TextDisabled("%s", label.c_str());
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace sculpt::ui
