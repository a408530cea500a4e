// SculptApp: where every input event goes (the keys and mouse of README's table).

#include "core/base/errors.h"
#include "ui/app/sculpt_app.h"
#include "ui/input/imgui_input.h"
#include "ui/window/window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <openvdb/Exceptions.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>

namespace sculpt::ui {

namespace {

constexpr double kWheelZoomStep = 1.15;

}  // namespace

void SculptApp::handle(const InputEvent& event)
{
    const bool scripted = event.type == EventType::Screenshot || event.type == EventType::Report ||
                          event.type == EventType::WaitForJob || event.type == EventType::Fault;
    if (!mOptions.record.empty() && !scripted) {
        mRecording.push_back(event);
    }
    if (event.type == EventType::Key) mPointer.track(event);
    // Tab is pieces mode's key: ImGui would move the focus into a panel's field with it (a field
    // being edited keeps it, for completion).
    if (!(event.type == EventType::Key && event.key == GLFW_KEY_TAB && !mItemActive)) feedImGui(event, mPointer.held());
    mLastInput = mWindow.time();
    mLastEventArrival = arrival(event);
    switch (event.type) {
    case EventType::Resize: mView.viewport().resize(event.width, event.height); break;
    case EventType::Quit:
        mTools.current().finish();  // closing the window ends the stroke, kept, then asks
        execute(Command::Quit);
        break;
    case EventType::Screenshot: mPendingScreenshots.emplace_back(event.text); break;
    case EventType::Report: mPendingReports.push_back(event); break;
    case EventType::Key: routeKey(event); break;
    case EventType::Text: break;
    case EventType::WaitForJob:
        if (mPlayer && holdsReplay()) mPlayer->hold(mWindow.time());
        break;
    case EventType::Fault: raiseFault(event.text); break;
    default: routeMouse(event); break;
    }
}

void SculptApp::raiseFault(const std::string& kind)
{
    if (kind == "bad_alloc") throw std::bad_alloc();
    if (kind == "openvdb") throw openvdb::RuntimeError("a fault event");
    throw std::runtime_error("a fault event");
}

void SculptApp::routeMouse(const InputEvent& event)
{
    const double dx = event.x - mPointer.x(), dy = event.y - mPointer.y();
    mPointer.track(event);
    const bool overPanel = ImGui::GetIO().WantCaptureMouse && mDrag == Drag::None && !mTools.current().holding();
    if (modalOpen() || (overPanel && event.type != EventType::MouseMove)) return;
    if (event.type == EventType::Wheel)
        mView.zoomAt(*mDocument, mPointer.x(), mPointer.y(), std::pow(kWheelZoomStep, event.y));
    else if (event.type == EventType::MouseButton && event.press) pressButton(event);
    else if (event.type == EventType::MouseButton) releaseButton(event);
    else dragTo(event, dx, dy);
}

void SculptApp::pressButton(const InputEvent& event)
{
    if (mDrag == Drag::Radius || mDrag == Drag::Strength) {
        mDrag = Drag::None;  // a click keeps the new size
        return;
    }
    Tool& tool = mTools.current();
    if (tool.holding()) {  // a gesture that runs without a button (G, R, S): any press ends it
        tool.press(event);
        return;
    }
    if (event.button == kLeftButton && !(event.mods & kAlt)) {
        if (mMode && tool.yieldsToMode()) {
            const std::optional<SurfaceHit> hit = pickAt(mPointer.x(), mPointer.y());  // a button event has no position
            if (hit && mMode->press(*hit)) {                                           // a primitive placed, say
                mDrag = Drag::Mode;
                return;
            }
        }
        if (tool.press(event)) return;
    }
    // Navigation: middle (Blender), right (SculptGL), Alt+left (touchpads), left off the model.
    mDrag = (event.mods & kShift) ? Drag::Pan : (event.mods & kControl) ? Drag::Zoom : Drag::Orbit;
}

void SculptApp::releaseButton(const InputEvent& event)
{
    if (mTools.current().holding()) mTools.current().release(event);
    if (mDrag != Drag::Radius && mDrag != Drag::Strength) mDrag = Drag::None;
}

void SculptApp::dragTo(const InputEvent& event, double dx, double dy)
{
    if (mTools.current().holding()) return mTools.current().drag(event);
    switch (mDrag) {
    case Drag::Mode:
        if (const std::optional<SurfaceHit> hit = pickAt(event.x, event.y)) mMode->drag(*hit);
        break;
    case Drag::Orbit: mView.camera().orbit(dx, dy); break;
    case Drag::Pan: mView.camera().pan(dx, dy); break;
    case Drag::Zoom: mView.camera().zoom(std::pow(1.01, -dy)); break;
    case Drag::Radius:
        mBrush.radius = std::max(0.5 * mDocument->session().field().voxelSize(),
                                 mDragStartValue * std::pow(2.0, (event.x - mDragStartX) / 120.0));
        break;
    case Drag::Strength:
        mBrush.strength = std::clamp(mDragStartValue + (event.x - mDragStartX) / 300.0, 0.01, 1.0);
        break;
    case Drag::None: break;
    }
}

void SculptApp::awaitFrame(const InputEvent& event, std::size_t stamps)
{
    mMeasures.stamps += stamps;
    if (mMeasures.pendingSince < 0.0) mMeasures.pendingSince = arrival(event);
}

void SculptApp::routeKey(const InputEvent& event)
{
    if (modifierOfKey(event.key) || !event.press) return;
    if (modalOpen()) return routeDialogKey(event);
    // A panel's field being edited takes its keys. ImGui's WantTextInput lags a frame (it still
    // claims keys for a prompt just closed): ask instead whether an item was active when the
    // last frame ended.
    if (mItemActive) return;
    // Esc over an open menu is meant for the menu, not for the panel behind it.
    const bool menuOpen = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
    if (menuOpen && event.key == GLFW_KEY_ESCAPE) return;
    if (mDrag == Drag::Radius || mDrag == Drag::Strength) {
        if (event.key == GLFW_KEY_ESCAPE) (mDrag == Drag::Radius ? mBrush.radius : mBrush.strength) = mDragStartValue;
        mDrag = Drag::None;
        return;
    }
    if (mTools.current().holding()) {  // a key during a stroke waits; G, R and S take theirs
        mTools.current().key(event);
        return;
    }
    if (mDrag != Drag::None) return;
    const std::optional<Scope> toolScope = mTools.current().keyScope();
    std::optional<Command> command = toolScope ? mCommands.forKey(event.key, event.mods, *toolScope) : std::nullopt;
    if (!command) command = mCommands.forKey(event.key, event.mods);
    if (command) execute(*command);
}

void SculptApp::routeDialogKey(const InputEvent& event)
{
    const std::optional<Command> command = mCommands.forKey(event.key, event.mods, Scope::Dialog);
    if (!command) return;
    // A field being edited keeps its keys, Enter too: what it holds reaches the dialog's settings
    // only when ImGui has read the keys typed before (okOrCancel hears that Enter). Esc closes.
    if (mItemActive && *command != Command::DialogCancel) return;
    if (whyNot(*command).empty()) execute(*command);  // a key this dialog does not take: nothing
}

}  // namespace sculpt::ui
