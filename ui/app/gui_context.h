// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file gui_context.h
/// @brief Dear ImGui's context for the window's panels: the same layout on every start, the keys
///        mapped, and its OpenGL renderer when the window draws (a headless window only lays the
///        panels out). One frame at a time.

namespace sculpt::ui {

class GuiContext {
public:
    /// `draws`: the window has a current OpenGL 3.2 context to draw the panels into.
    explicit GuiContext(bool draws);
    ~GuiContext();
    GuiContext(const GuiContext&) = delete;
    GuiContext& operator=(const GuiContext&) = delete;

    /// Starts a frame of `width` x `height` pixels, `deltaSeconds` after the last: panels draw now.
    void beginFrame(int width, int height, double deltaSeconds);
    /// Ends the frame, drawing the panels over the view (if the window draws).
    void endFrame(int width, int height);
    /// An item (a text field being edited, a slider held) was active when the last frame ended:
    /// it takes the keys. ImGui's WantTextInput lags a frame (it still claims keys for a prompt
    /// just closed).
    bool itemActive() const { return mItemActive; }

private:
    bool mDraws;
    bool mItemActive = false;
};

}  // namespace sculpt::ui
