// SPDX-License-Identifier: Apache-2.0
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

namespace sculpt::ui {

void beginSidePanel(const char* title, float width)
{
    // Under the brush palette: the history stays in view on the right.
    ImGui::SetNextWindowPos(ImVec2(8.f, 312.f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, 0.f), ImGuiCond_Always);
    ImGui::Begin(title, nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
}

void warningText(const std::string& text, float width)
{
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::TextColored(ImVec4(1.f, 0.6f, 0.35f, 1.f), "%s", text.c_str());
    ImGui::PopTextWrapPos();
}

}  // namespace sculpt::ui
