// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file headless_window.h
/// @brief A window with no display and no OpenGL: the application runs whole (input routing,
///        tools, commands, jobs, meshing, the panels' logic) and draws nothing. For tests that
///        drive the window without Xvfb, and for replays in batch (sculpt-ui --headless).

#include "ui/window/window.h"

#include <chrono>

namespace sculpt::ui {

class HeadlessWindow final : public Window {
public:
    HeadlessWindow(int width, int height) : mWidth(width), mHeight(height) {}

    void setListener(std::function<void(const InputEvent&)> listener) override { mListener = std::move(listener); }
    /// No input ever arrives: waits out the timeout, as an idle window would.
    void pollEvents(double timeoutSeconds) override;
    void swapBuffers() override {}
    void setTitle(const std::string& title) override { mTitle = title; }
    void resize(int width, int height) override;
    int width() const override { return mWidth; }
    int height() const override { return mHeight; }
    double time() const override;
    bool draws() const override { return false; }

    const std::string& title() const { return mTitle; }

private:
    int mWidth, mHeight;
    std::string mTitle;
    std::function<void(const InputEvent&)> mListener;
    std::chrono::steady_clock::time_point mOpened = std::chrono::steady_clock::now();
};

}  // namespace sculpt::ui
