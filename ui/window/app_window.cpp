// SPDX-License-Identifier: Apache-2.0
#include "ui/window/app_window.h"

#include <GLFW/glfw3.h>

namespace sculpt::ui {

namespace {

AppWindow* owner(GLFWwindow* window) { return static_cast<AppWindow*>(glfwGetWindowUserPointer(window)); }

InputEvent eventOf(EventType type, double x = 0.0, double y = 0.0)
{
    InputEvent e;
    e.type = type;
    e.x = x, e.y = y;
    return e;
}

std::string glfwError()
{
    const char* text = nullptr;
    glfwGetError(&text);
    return text ? text : "unknown reason";
}

}  // namespace

AppWindow::AppWindow(int width, int height, const std::string& title)
{
    if (!glfwInit()) throw WindowUnavailable("cannot open a window: " + glfwError());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 2);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 0);  // VTK renders into its own framebuffer
    // X11's WM_CLASS: the launcher's StartupWMClass, so the desktop groups the window with it.
    glfwWindowHintString(GLFW_X11_CLASS_NAME, "sculpt-ui");
    glfwWindowHintString(GLFW_X11_INSTANCE_NAME, "sculpt-ui");
    mWindow = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!mWindow) {
        const std::string why = glfwError();
        glfwTerminate();
        throw WindowUnavailable("cannot open an OpenGL 3.2 window: " + why);
    }
    glfwMakeContextCurrent(mWindow);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(mWindow, this);
    installCallbacks();
}

AppWindow::~AppWindow()
{
    glfwDestroyWindow(mWindow);
    glfwTerminate();
}

void AppWindow::installCallbacks()
{
    glfwSetCursorPosCallback(
        mWindow, [](GLFWwindow* w, double x, double y) { owner(w)->deliver(eventOf(EventType::MouseMove, x, y)); });
    glfwSetScrollCallback(
        mWindow, [](GLFWwindow* w, double dx, double dy) { owner(w)->deliver(eventOf(EventType::Wheel, dx, dy)); });
    glfwSetMouseButtonCallback(mWindow, [](GLFWwindow* w, int button, int action, int mods) {
        if (button > kMiddleButton) return;
        InputEvent e = eventOf(EventType::MouseButton);
        e.button = button, e.press = action == GLFW_PRESS, e.mods = mods;
        owner(w)->deliver(e);
    });
    glfwSetKeyCallback(mWindow, [](GLFWwindow* w, int key, int, int action, int mods) {
        if (action == GLFW_REPEAT || keyName(key).empty()) return;
        InputEvent e = eventOf(EventType::Key);
        e.key = key, e.press = action == GLFW_PRESS, e.mods = mods;
        owner(w)->deliver(e);
    });
    glfwSetCharCallback(mWindow, [](GLFWwindow* w, unsigned codepoint) {
        if (codepoint >= 0x80) return;  // the recordings are ASCII; ImGui's default font is too
        InputEvent e = eventOf(EventType::Text);
        e.text = std::string(1, char(codepoint));
        owner(w)->deliver(e);
    });
    glfwSetFramebufferSizeCallback(mWindow, [](GLFWwindow* w, int width, int height) {
        InputEvent e = eventOf(EventType::Resize);
        e.width = width, e.height = height;
        owner(w)->deliver(e);
    });
    glfwSetDropCallback(mWindow, [](GLFWwindow* w, int count, const char** paths) {
        if (count < 1) return;  // one document at a time: the first of several
        InputEvent e = eventOf(EventType::Drop);
        e.text = paths[0];
        owner(w)->deliver(e);
    });
    glfwSetWindowCloseCallback(mWindow, [](GLFWwindow* w) {
        glfwSetWindowShouldClose(w, GLFW_FALSE);  // the application decides (unsaved changes)
        owner(w)->deliver(eventOf(EventType::Quit));
    });
}

void AppWindow::deliver(InputEvent event)
{
    event.time = time();
    if (event.type == EventType::MouseMove) {
        // GLFW gives the pointer in screen coordinates; everything here is in framebuffer pixels
        // (they differ on high-density displays).
        int windowWidth = 0, windowHeight = 0;
        glfwGetWindowSize(mWindow, &windowWidth, &windowHeight);
        if (windowWidth > 0 && windowHeight > 0) {
            event.x *= double(width()) / windowWidth;
            event.y *= double(height()) / windowHeight;
        }
    }
    if (mListener) mListener(event);
}

void AppWindow::pollEvents(double timeoutSeconds)
{
    if (timeoutSeconds > 0.0) glfwWaitEventsTimeout(timeoutSeconds);
    else glfwPollEvents();
}

void AppWindow::swapBuffers() { glfwSwapBuffers(mWindow); }
void AppWindow::setIcon(const std::vector<IconImage>& sizes)
{
    std::vector<GLFWimage> images;
    for (const IconImage& size : sizes)
        images.push_back({size.width, size.height, const_cast<unsigned char*>(size.rgba.data())});
    if (!images.empty()) glfwSetWindowIcon(mWindow, int(images.size()), images.data());
}

void AppWindow::setTitle(const std::string& title)
{
    if (title == mTitle) return;  // the window manager's round trip, every frame otherwise
    glfwSetWindowTitle(mWindow, title.c_str());
    mTitle = title;
}
void AppWindow::resize(int width, int height)
{
    // Framebuffer pixels asked for; the window is sized in screen coordinates.
    int framebufferWidth = 0, framebufferHeight = 0, windowWidth = 0, windowHeight = 0;
    glfwGetFramebufferSize(mWindow, &framebufferWidth, &framebufferHeight);
    glfwGetWindowSize(mWindow, &windowWidth, &windowHeight);
    const double scale = framebufferWidth > 0 ? double(windowWidth) / framebufferWidth : 1.0;
    glfwSetWindowSize(mWindow, int(width * scale + 0.5), int(height * scale + 0.5));
}

int AppWindow::width() const
{
    int w = 0, h = 0;
    glfwGetFramebufferSize(mWindow, &w, &h);
    return w;
}

int AppWindow::height() const
{
    int w = 0, h = 0;
    glfwGetFramebufferSize(mWindow, &w, &h);
    return h;
}

double AppWindow::time() const { return glfwGetTime(); }

}  // namespace sculpt::ui
