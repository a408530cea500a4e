// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file window.h
/// @brief What the application needs of its window: events delivered as InputEvents, a size, a
///        clock, a title, and whether it has an OpenGL context to draw into. A GLFW window for
///        people (AppWindow), a headless one for tests and batch replays (HeadlessWindow).
///
/// Sizes and pointer positions are in framebuffer pixels, the unit VTK and ImGui draw in.

#include "ui/input/input_event.h"

#include <functional>
#include <string>

namespace sculpt::ui {

class Window {
public:
    virtual ~Window() = default;

    /// Receives every live event (input, resize, close) as it arrives.
    virtual void setListener(std::function<void(const InputEvent&)> listener) = 0;
    /// Delivers pending events to the listener; waits up to `timeoutSeconds` for one (0: none).
    virtual void pollEvents(double timeoutSeconds) = 0;
    virtual void swapBuffers() = 0;
    /// Shows `title`; called every frame, so cheap when it is the one shown.
    virtual void setTitle(const std::string& title) = 0;
    /// As a user resizing the window (a replayed resize), to this many framebuffer pixels.
    virtual void resize(int width, int height) = 0;
    virtual int width() const = 0;
    virtual int height() const = 0;
    /// Seconds since the window opened.
    virtual double time() const = 0;
    /// It holds a current OpenGL 3.2 context the view and panels draw into; false: nothing is
    /// drawn (the model, its meshes and the panels' logic all run).
    virtual bool draws() const = 0;
};

}  // namespace sculpt::ui
