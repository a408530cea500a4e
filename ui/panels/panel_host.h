// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file panel_host.h
/// @brief What a panel (and a mode's panel) may reach: the commands, the workspace and its
///        files, the view, the brush, the tools, the dialogs' state, the status figures and the
///        pointer. The window implements it; panels never see the window itself.

#include "ui/commands/command_registry.h"
#include "ui/files/document_files.h"
#include "ui/input/pointer_state.h"
#include "ui/panels/dialogs.h"
#include "ui/scene/document_view.h"
#include "ui/sculpting/brush_options.h"
#include "ui/status/status_tally.h"
#include "ui/tools/tool_box.h"
#include "ui/workspace/workspace.h"

#include <optional>
#include <string>

namespace sculpt::ui {

class PanelHost {
public:
    /// Runs `command` if it can run now; else the status bar says why.
    virtual void execute(Command command) = 0;
    virtual const CommandRegistry& commands() const = 0;
    virtual Workspace& workspace() = 0;
    virtual DocumentFiles& files() = 0;
    virtual DocumentView& view() = 0;
    virtual BrushOptions& brush() = 0;
    virtual ToolBox& tools() = 0;
    virtual Dialogs& dialogs() = 0;
    virtual const StatusFigures& status() const = 0;
    virtual const PointerState& pointerState() const = 0;
    /// Seconds on the window's clock.
    virtual double time() const = 0;

    // Shorthands for what panels reach most.
    std::string whyNot(Command command) const { return commands().whyNot(command); }
    Document& document() { return workspace().document(); }
    Notices& notices() { return workspace().notices(); }
    SurfaceLook& look() { return view().look(); }
    CameraControl& camera() { return view().camera(); }
    /// The sculpted piece's surface under the pointer, in its field's world.
    std::optional<SurfaceHit> hitUnderPointer()
    {
        return view().pickAt(document(), pointerState().x(), pointerState().y());
    }

protected:
    ~PanelHost() = default;
};

}  // namespace sculpt::ui
