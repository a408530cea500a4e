// SPDX-License-Identifier: Apache-2.0
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

namespace sculpt::ui {

namespace {

constexpr const char* kMouse[][2] = {
    {"Left drag on the model", "sculpt with the current tool"},
    {"Ctrl + left drag", "inverted tool (add/carve, inflate/deflate)"},
    {"Shift + left drag", "smooth"},
    {"Left drag off the model", "orbit"},
    {"Middle or right drag", "orbit"},
    {"Shift + middle/right drag", "pan"},
    {"Ctrl + middle/right drag", "zoom"},
    {"Alt + left drag", "orbit (touchpad); with Shift pan, with Ctrl zoom"},
    {"Wheel", "zoom towards the cursor"},
};

/// The commands of `scope` that have keys: keys, name, help.
void keyTable(const CommandRegistry& commands, const char* title, Scope scope)
{
    ImGui::Separator();
    ImGui::TextUnformatted(title);
    if (!ImGui::BeginTable(title, 3, ImGuiTableFlags_RowBg)) return;
    // Keys and names fixed, the help wrapped to what is left: nothing is cut off.
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, 160.f);
    ImGui::TableSetupColumn("command", ImGuiTableColumnFlags_WidthFixed, 130.f);
    ImGui::TableSetupColumn("help", ImGuiTableColumnFlags_WidthStretch);
    for (const CommandRow& info : commands.rows()) {
        const std::string keys = commands.shortcutText(info.command);
        if (keys.empty() || info.scope != scope) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(keys.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(info.label);
        ImGui::TableNextColumn();
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", info.help);
        ImGui::PopStyleColor();
    }
    ImGui::EndTable();
}

}  // namespace

void drawHelpPanel(PanelHost& host)
{
    ImGui::SetNextWindowSize(ImVec2(720, 600), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImVec2(260, 40), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Help", &host.dialogs().help)) return ImGui::End();
    ImGui::TextUnformatted("Mouse");
    if (ImGui::BeginTable("mouse", 2, ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("input", ImGuiTableColumnFlags_WidthFixed, 220.f);
        ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
        for (const auto& row : kMouse) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[1]);
        }
        ImGui::EndTable();
    }
    keyTable(host.commands(), "Keys", Scope::View);
    keyTable(host.commands(), "In pieces mode (Tab)", Scope::Pieces);
    keyTable(host.commands(), "In a dialog", Scope::Dialog);
    ImGui::End();
}

}  // namespace sculpt::ui
