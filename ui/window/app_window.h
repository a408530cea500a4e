#pragma once
/// @file app_window.h
/// @brief The GLFW window and its OpenGL 3.2 core context; turns GLFW callbacks into InputEvents.
///
/// Sizes and pointer positions are in framebuffer pixels, the unit VTK and ImGui draw in.

#include "ui/input/input_event.h"

#include <functional>
#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace sculpt::ui {

/// No window could be opened here (no display, an unusable one, no OpenGL 3.2): sculpt-ui exits
/// 2 with the reason, and scripts/demo.sh goes headless.
struct WindowUnavailable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class AppWindow {
public:
    /// Opens a window of `width` x `height` pixels with a current OpenGL 3.2 core context.
    /// @throws WindowUnavailable saying why.
    AppWindow(int width, int height, const std::string& title);
    ~AppWindow();
    AppWindow(const AppWindow&) = delete;
    AppWindow& operator=(const AppWindow&) = delete;

    /// Receives every live event (input, resize, close) as it arrives.
    void setListener(std::function<void(const InputEvent&)> listener) { mListener = std::move(listener); }

    /// Delivers pending events to the listener; waits up to `timeoutSeconds` for one (0: none).
    void pollEvents(double timeoutSeconds);
    void swapBuffers();
    void setTitle(const std::string& title);
    /// As a user resizing the window (a replayed resize), to this many framebuffer pixels.
    void resize(int width, int height);

    int width() const;
    int height() const;
    /// Seconds since the window opened.
    double time() const;
    GLFWwindow* handle() const { return mWindow; }

private:
    void deliver(InputEvent event);
    void installCallbacks();

    GLFWwindow* mWindow = nullptr;
    std::function<void(const InputEvent&)> mListener;
};

}  // namespace sculpt::ui
