// SPDX-License-Identifier: Apache-2.0
#include "ui/app/gui_context.h"

#include "ui/input/imgui_input.h"

#include <imgui.h>
#include <vtk_glew.h>  // the OpenGL calls made here, as VTK loads them (no other GL header)

#include <backends/imgui_impl_opengl3.h>

namespace sculpt::ui {

GuiContext::GuiContext(bool draws) : mDraws(draws)
{
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the same layout on every start (and in every test)
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.f;
    ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 0.88f;
    setUpImGuiKeys();
    if (mDraws) {
        ImGui_ImplOpenGL3_Init("#version 150");
    } else {  // what the renderer's set-up would do: the panels lay out text in the font
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        ImGui::GetIO().Fonts->GetTexDataAsAlpha8(&pixels, &width, &height);
    }
}

GuiContext::~GuiContext()
{
    if (mDraws) ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

void GuiContext::beginFrame(int width, int height, double deltaSeconds)
{
    if (mDraws) ImGui_ImplOpenGL3_NewFrame();
    beginImGuiFrame(width, height, deltaSeconds);
    ImGui::NewFrame();
}

void GuiContext::endFrame(int width, int height)
{
    mItemActive = ImGui::IsAnyItemActive();
    ImGui::Render();
    if (!mDraws) return;
    glViewport(0, 0, width, height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace sculpt::ui
