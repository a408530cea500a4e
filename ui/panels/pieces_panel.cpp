// SPDX-License-Identifier: Apache-2.0
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

namespace sculpt::ui {

namespace {

constexpr std::size_t kSwatches = 8;

ImVec4 colourOf(const openvdb::Vec3f& c) { return ImVec4(c[0], c[1], c[2], 1.f); }

/// One row per piece: its colour, an eye (shown or hidden) and its name, selected if sculpted.
void pieceList(PanelHost& host, PiecesTool& tool)
{
    const Document& doc = host.document();
    for (std::size_t i = 0; i < doc.pieces().size(); ++i) {
        const PieceLook& look = doc.pieces()[i].look;
        ImGui::PushID(int(i));
        ImGui::ColorButton("##colour", colourOf(look.colour), ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
        ImGui::SameLine();
        bool visible = look.visible;
        if (ImGui::Checkbox("##shown", &visible)) {
            std::vector<PieceLook> looks = tool.looks();
            looks[i].visible = visible;
            tool.changeLooks(std::move(looks), (visible ? "show '" : "hide '") + look.name + "'");
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("shown (hidden pieces are neither drawn nor in the way)");
        ImGui::SameLine();
        if (ImGui::Selectable(look.name.c_str(), i == doc.activePiece())) tool.select(i);
        ImGui::PopID();
    }
}

/// The sculpted piece's name, colour and edits.
void activePiece(PanelHost& host, PiecesTool& tool, PieceNameField& d)
{
    const Document& doc = host.document();
    const std::size_t index = doc.activePiece();
    const PieceLook& look = doc.pieces()[index].look;
    if (d.of != index || d.seen != look.name) {  // another piece, or renamed (undo)
        d.text = look.name;
        d.of = index;
        d.seen = look.name;
    }
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "%s", d.text.c_str());
    ImGui::SetNextItemWidth(150);
    if (ImGui::InputText("name", buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue) && buffer[0] &&
        look.name != buffer) {
        if (doc.freeName(buffer) != buffer) {
            host.notices().say(std::string("a piece is named '") + buffer + "' already");
        } else {
            std::vector<PieceLook> looks = tool.looks();
            looks[index].name = buffer;
            tool.changeLooks(std::move(looks), "rename '" + look.name + "' to '" + buffer + "'");
        }
    }
    d.text = buffer;
    for (std::size_t k = 0; k < kSwatches; ++k) {
        ImGui::PushID(int(k));
        if (ImGui::ColorButton("##swatch", colourOf(paletteColour(k)), 0, ImVec2(20, 20))) {
            std::vector<PieceLook> looks = tool.looks();
            looks[index].colour = paletteColour(k);
            tool.changeLooks(std::move(looks), "colour '" + look.name + "'");
        }
        ImGui::PopID();
        if (k + 1 < kSwatches) ImGui::SameLine();
    }
    commandButton(host, Command::SoloPiece);
    ImGui::SameLine();
    commandButton(host, Command::DuplicatePiece);
    ImGui::SameLine();
    commandButton(host, Command::DeletePiece);
    commandButton(host, Command::SplitPiece);
    ImGui::SameLine();
    commandButton(host, Command::ApplyPlacement);
    if (doc.pieces().size() > 1) {
        const std::size_t with = tool.mergePartner();
        ImGui::SetNextItemWidth(110);
        if (ImGui::BeginCombo("##with", doc.pieces()[with].look.name.c_str())) {
            for (std::size_t i = 0; i < doc.pieces().size(); ++i)
                if (i != index && ImGui::Selectable(doc.pieces()[i].look.name.c_str(), i == with))
                    tool.setMergePartner(i);
            ImGui::EndCombo();
        }
        ImGui::SameLine();
        commandButton(host, Command::MergePieces);
    }
}

}  // namespace

void drawPiecesPanel(PanelHost& host)
{
    PiecesTool& tool = host.tools().get<PiecesTool>();
    const bool piecesMode = host.tools().isCurrent(tool);
    if (host.document().pieces().size() < 2 && !piecesMode) return;
    const ImVec2 size(236, 0);
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - size.x - 8, 296), ImGuiCond_Always);
    ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    ImGui::Begin("Pieces", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    pieceList(host, tool);
    ImGui::Separator();
    activePiece(host, tool, host.dialogs().pieceName);
    ImGui::Separator();
    bool modeOn = piecesMode;
    if (ImGui::Checkbox("pieces mode", &modeOn)) host.execute(Command::PiecesMode);
    commandTooltip(host, Command::PiecesMode);
    ImGui::SameLine();
    ImGui::Checkbox("push", &tool.push());
    commandTooltip(host, Command::TogglePush);
    ImGui::Checkbox("strokes stop at other pieces", &host.brush().stopAtPieces);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("clay added to this piece stops where another piece is (the others are never edited)");
    if (piecesMode) ImGui::TextDisabled("click picks; G R S move it");
    ImGui::End();
}

}  // namespace sculpt::ui
