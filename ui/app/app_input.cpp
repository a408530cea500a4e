// SPDX-License-Identifier: Apache-2.0
// SculptApp: where every input event goes (the keys and mouse of README's table): the dialogs,
// the tool, the open mode or the camera.

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "ui/app/sculpt_app.h"
#include "ui/input/imgui_input.h"
#include "ui/window/window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <openvdb/Exceptions.h>

#include <cmath>
#include <new>
#include <stdexcept>

namespace sculpt::ui {

namespace {

constexpr double kWheelZoomStep = 1.15;

/// A fault event's internal error (tests of the recovery from one).
[[noreturn]] void raiseFault(const std::string& kind)
{
    if (kind == "bad_alloc") throw std::bad_alloc();
    if (kind == "openvdb") throw openvdb::RuntimeError("a fault event");
    throw std::runtime_error("a fault event");
}

/// A dialog is open: it takes every key, and the mouse does nothing in the view.
bool modalOpen(const Dialogs& dialogs, const DocumentFiles& files, const Notices& notices)
{
    return dialogs.prompt.open() || files.asking() || !notices.error().empty();
}

}  // namespace

void SculptApp::handle(const InputEvent& event)
{
    mReplay.note(event);
    if (event.type == EventType::Key) mPointer.track(event);
    // Tab is pieces mode's key: ImGui would move the focus into a panel's field with it (a field
    // being edited keeps it, for completion).
    if (!(event.type == EventType::Key && event.key == GLFW_KEY_TAB && !mGui.itemActive()))
        feedImGui(event, mPointer.held());
    mFrames.input(mWindow.time(), mReplay.arrival(event));
    switch (event.type) {
    case EventType::Resize: mView.viewport().resize(event.width, event.height); break;
    case EventType::Quit:
        mTools.current().finish();  // closing the window ends the stroke, kept, then asks
        execute(Command::Quit);
        break;
    case EventType::Screenshot:
    case EventType::Report:
    case EventType::Text: break;
    case EventType::Key: routeKey(event); break;
    case EventType::WaitForJob:
        if (mReplay.player() && holdsReplay()) mReplay.player()->hold(mWindow.time());
        break;
    case EventType::Fault: raiseFault(event.text);
    case EventType::Drop: openDropped(event.text); break;
    default: routeMouse(event); break;
    }
}

void SculptApp::openDropped(const std::string& path)
{
    // As File > Open (a document) or File > Import (a scan, a mesh) of that path, confirmed at
    // once; after "save changes?" if it comes first (the prompt then waits, filled in).
    mDialogs.dropped = path;
    execute(lowerExtension(path) == ".vdb" ? Command::Open : Command::Import);
    if (mDialogs.prompt.open() && mDialogs.prompt.path == path) mDialogs.confirm(mWork.notices());
    else if (!mFiles.asking()) mDialogs.dropped.clear();  // busy: dropped on a job, nothing opens
}

void SculptApp::routeMouse(const InputEvent& event)
{
    const double dx = event.x - mPointer.x(), dy = event.y - mPointer.y();
    mPointer.track(event);
    const bool overPanel = ImGui::GetIO().WantCaptureMouse && !mDrag.active() && !mTools.current().holding();
    if (modalOpen(mDialogs, mFiles, mWork.notices()) || (overPanel && event.type != EventType::MouseMove)) return;
    if (!mDrag.active() && !mTools.current().holding() &&
        mView.sliceMouse(mWork.document(), event, mPointer.x(), mPointer.y()))
        return;
    if (event.type == EventType::Wheel)
        mView.zoomAt(mWork.document(), mPointer.x(), mPointer.y(), std::pow(kWheelZoomStep, event.y));
    else if (event.type == EventType::MouseButton && event.press) pressButton(event);
    else if (event.type == EventType::MouseButton) releaseButton(event);
    else dragTo(event, dx, dy);
}

void SculptApp::pressButton(const InputEvent& event)
{
    if (mDrag.adjusting()) return mDrag.end(false, mBrush);  // a click keeps the new setting
    Tool& tool = mTools.current();
    if (tool.holding()) {  // a gesture that runs without a button (G, R, S): any press ends it
        tool.press(event);
        return;
    }
    if (event.button == kLeftButton && !(event.mods & kAlt)) {
        Mode* mode = mModes.get();
        if (mode && tool.yieldsToMode()) {
            // A button event has no position: the pointer's.
            const std::optional<SurfaceHit> hit = mView.pickAt(mWork.document(), mPointer.x(), mPointer.y());
            if (hit && mode->press(*hit)) return mDrag.grabHandle();  // a primitive placed, say
        }
        if (tool.press(event)) return;
    }
    mDrag.grabCamera(event.mods);
}

void SculptApp::releaseButton(const InputEvent& event)
{
    if (mTools.current().holding()) mTools.current().release(event);
    mDrag.release();
}

void SculptApp::dragTo(const InputEvent& event, double dx, double dy)
{
    if (mTools.current().holding()) return mTools.current().drag(event);
    if (mDrag.kind() != ViewDrag::Kind::Mode)
        return mDrag.follow(event.x, dx, dy, mView.camera(), mBrush,
                            0.5 * mWork.document().session().field().voxelSize());
    Mode* mode = mModes.get();
    const std::optional<SurfaceHit> hit = mView.pickAt(mWork.document(), event.x, event.y);
    if (mode && hit) mode->drag(*hit);
}

void SculptApp::routeKey(const InputEvent& event)
{
    if (modifierOfKey(event.key) || !event.press) return;
    if (modalOpen(mDialogs, mFiles, mWork.notices())) return routeDialogKey(event);
    // A panel's field being edited takes its keys.
    if (mGui.itemActive()) return;
    // Esc over an open menu is meant for the menu, not for the panel behind it.
    const bool menuOpen = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
    if (menuOpen && event.key == GLFW_KEY_ESCAPE) return;
    if (mDrag.adjusting()) return mDrag.end(event.key == GLFW_KEY_ESCAPE, mBrush);  // Esc restores, a key keeps
    if (mTools.current().holding()) {  // a key during a stroke waits; G, R and S take theirs
        mTools.current().key(event);
        return;
    }
    if (mDrag.active()) return;
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
    if (mGui.itemActive() && *command != Command::DialogCancel) return;
    if (mCommands.whyNot(*command).empty()) execute(*command);  // a key this dialog does not take: nothing
}

}  // namespace sculpt::ui
