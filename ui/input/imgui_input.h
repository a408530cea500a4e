// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file imgui_input.h
/// @brief Feeds InputEvents (live or replayed) to Dear ImGui through its io, before NewFrame.
///
/// ImGui's GLFW backend would poll the real mouse and keyboard, which a replay does not move;
/// so the backend renders only and this file is ImGui's input. ImGui 1.86 reads button and key
/// states once per frame: a press and its release must reach it in different frames (the
/// event player ends a frame after each).

#include "ui/input/input_event.h"

namespace sculpt::ui {

/// Maps ImGui's navigation keys to GLFW key codes (ImGui 1.86 io.KeyMap).
void setUpImGuiKeys();
/// `heldMods`: the modifier keys held down (from their own key events). A key's own modifiers
/// count while it is down; a replayed tap of Ctrl+S leaves no Ctrl held after it.
void feedImGui(const InputEvent& event, int heldMods);
/// Display size and time step for the coming frame.
void beginImGuiFrame(int width, int height, double deltaSeconds);
/// Ends a frame an exception cut short (windows left open included), so the next starts clean.
void abandonImGuiFrame();

}  // namespace sculpt::ui
