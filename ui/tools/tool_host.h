// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file tool_host.h
/// @brief What a tool may reach: the workspace (the document, its edits and jobs, the notices),
///        the brush, the view it is seen in, the pointer and the frames' log. The window
///        implements it; tools never see the window itself.

#include "ui/input/pointer_state.h"
#include "ui/scene/document_view.h"
#include "ui/sculpting/brush_options.h"
#include "ui/status/frame_log.h"
#include "ui/workspace/workspace.h"

#include <glm/vec2.hpp>
#include <openvdb/Types.h>

#include <optional>
#include <string>

namespace sculpt::ui {

class ToolHost {
public:
    virtual Workspace& workspace() = 0;
    virtual BrushOptions& brush() = 0;
    virtual DocumentView& view() = 0;
    virtual const PointerState& pointerState() const = 0;
    virtual FrameLog& frames() = 0;

    // Shorthands for what tools reach most.
    Document& document() { return workspace().document(); }
    const Viewport& viewport() { return view().viewport(); }
    const CameraControl& camera() { return view().camera(); }
    /// The picker the hover uses: a stroke freezes its box while it runs.
    SurfacePicker& picker() { return view().picker(); }
    /// The sculpted piece's surface under the pixel, in its field's world (where edits are made).
    std::optional<SurfaceHit> pickAt(double x, double y) { return view().pickAt(document(), x, y); }
    /// A hit of pickAt in the world (the piece's placement applied).
    SurfaceHit inWorld(const SurfaceHit& hit) { return view().inWorld(document(), hit); }
    /// The pointer, in window pixels.
    glm::dvec2 pointer() const { return {pointerState().x(), pointerState().y()}; }
    /// The modifier keys held down now.
    int heldMods() const { return pointerState().held(); }
    std::string waitReason() { return workspace().waitReason(); }
    bool busy() { return workspace().busy(); }
    void notify(std::string notice) { workspace().notices().say(std::move(notice)); }
    void showError(const std::string& message) { workspace().notices().fail(message); }
    /// Draws the sculpted piece at `placement` (a gesture under way), not where the document has it.
    void showPlacement(const openvdb::Mat4d& placement) { view().display().setPlacement(placement); }
    /// The input being handled changed the model by `stamps` stamps: the frames measure when it
    /// is on screen.
    void awaitFrame(std::size_t stamps) { frames().awaitStamps(stamps); }

protected:
    ~ToolHost() = default;
};

}  // namespace sculpt::ui
