// SPDX-License-Identifier: Apache-2.0
#include "ui/input/imgui_input.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // the frame-scope flag and the error recovery, for abandonImGuiFrame

namespace sculpt::ui {

void setUpImGuiKeys()
{
    ImGuiIO& io = ImGui::GetIO();
    const std::pair<ImGuiKey_, int> keys[] = {
        {ImGuiKey_Tab, GLFW_KEY_TAB},
        {ImGuiKey_LeftArrow, GLFW_KEY_LEFT},
        {ImGuiKey_RightArrow, GLFW_KEY_RIGHT},
        {ImGuiKey_UpArrow, GLFW_KEY_UP},
        {ImGuiKey_DownArrow, GLFW_KEY_DOWN},
        {ImGuiKey_PageUp, GLFW_KEY_PAGE_UP},
        {ImGuiKey_PageDown, GLFW_KEY_PAGE_DOWN},
        {ImGuiKey_Home, GLFW_KEY_HOME},
        {ImGuiKey_End, GLFW_KEY_END},
        {ImGuiKey_Delete, GLFW_KEY_DELETE},
        {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE},
        {ImGuiKey_Space, GLFW_KEY_SPACE},
        {ImGuiKey_Enter, GLFW_KEY_ENTER},
        {ImGuiKey_Escape, GLFW_KEY_ESCAPE},
        {ImGuiKey_KeyPadEnter, GLFW_KEY_KP_ENTER},
        {ImGuiKey_A, GLFW_KEY_A},
        {ImGuiKey_C, GLFW_KEY_C},
        {ImGuiKey_V, GLFW_KEY_V},
        {ImGuiKey_X, GLFW_KEY_X},
        {ImGuiKey_Y, GLFW_KEY_Y},
        {ImGuiKey_Z, GLFW_KEY_Z},
    };
    for (const auto& [imgui, glfw] : keys) io.KeyMap[imgui] = glfw;
}

void feedImGui(const InputEvent& event, int heldMods)
{
    ImGuiIO& io = ImGui::GetIO();
    switch (event.type) {
    case EventType::MouseMove: io.MousePos = ImVec2(float(event.x), float(event.y)); break;
    case EventType::MouseButton: io.MouseDown[event.button] = event.press; break;
    case EventType::Wheel:
        io.MouseWheelH += float(event.x);
        io.MouseWheel += float(event.y);
        break;
    case EventType::Key: {
        if (event.key >= 0 && event.key < int(IM_ARRAYSIZE(io.KeysDown))) io.KeysDown[event.key] = event.press;
        const int mods = heldMods | (event.press ? event.mods : 0);
        io.KeyCtrl = mods & kControl;
        io.KeyShift = mods & kShift;
        io.KeyAlt = mods & kAlt;
        break;
    }
    case EventType::Text:
        for (unsigned char c : event.text) io.AddInputCharacter(c);
        break;
    default: break;
    }
}

void beginImGuiFrame(int width, int height, double deltaSeconds)
{
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DisplayFramebufferScale = ImVec2(1.f, 1.f);
    io.DeltaTime = float(deltaSeconds > 1e-4 ? deltaSeconds : 1e-4);
}

void abandonImGuiFrame()
{
    const ImGuiContext* context = ImGui::GetCurrentContext();
    if (!context || !context->WithinFrameScope) return;
    ImGui::ErrorCheckEndFrameRecover(nullptr);
    ImGui::EndFrame();
}

}  // namespace sculpt::ui
