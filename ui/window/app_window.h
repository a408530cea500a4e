// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file app_window.h
/// @brief The GLFW window and its OpenGL 3.2 core context; turns GLFW callbacks into InputEvents.
///
/// Sizes and pointer positions are in framebuffer pixels, the unit VTK and ImGui draw in.

#include "ui/window/window.h"

#include <stdexcept>
#include <vector>

struct GLFWwindow;

namespace sculpt::ui {

/// No window could be opened here (no display, an unusable one, no OpenGL 3.2): sculpt-ui exits
/// 2 with the reason, and scripts/demo.sh goes headless.
struct WindowUnavailable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// An icon's image: RGBA, 8 bits a channel, top row first.
struct IconImage {
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;
};

class AppWindow final : public Window {
public:
    /// Opens a window of `width` x `height` pixels with a current OpenGL 3.2 core context.
    /// @throws WindowUnavailable saying why.
    AppWindow(int width, int height, const std::string& title);
    ~AppWindow() override;
    AppWindow(const AppWindow&) = delete;
    AppWindow& operator=(const AppWindow&) = delete;

    void setListener(std::function<void(const InputEvent&)> listener) override { mListener = std::move(listener); }
    void pollEvents(double timeoutSeconds) override;
    void swapBuffers() override;
    void setTitle(const std::string& title) override;
    /// The window's icon, in the sizes given (the system picks one).
    void setIcon(const std::vector<IconImage>& sizes);
    void resize(int width, int height) override;
    int width() const override;
    int height() const override;
    double time() const override;
    bool draws() const override { return true; }

private:
    void deliver(InputEvent event);
    void installCallbacks();

    GLFWwindow* mWindow = nullptr;
    std::function<void(const InputEvent&)> mListener;
    std::string mTitle;  // shown
};

}  // namespace sculpt::ui
