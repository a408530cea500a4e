// SPDX-License-Identifier: Apache-2.0
#include "ui/window/headless_window.h"

#include <thread>

namespace sculpt::ui {

void HeadlessWindow::pollEvents(double timeoutSeconds)
{
    if (timeoutSeconds > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(timeoutSeconds));
}

void HeadlessWindow::resize(int width, int height)
{
    mWidth = width;
    mHeight = height;
    InputEvent event;
    event.type = EventType::Resize;
    event.width = width, event.height = height;
    event.time = time();
    if (mListener) mListener(event);  // as GLFW's framebuffer callback does
}

double HeadlessWindow::time() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - mOpened).count();
}

}  // namespace sculpt::ui
