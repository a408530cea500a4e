#pragma once
/// @file tool_host.h
/// @brief What a tool may ask of the window: the document and the brush, the view it sees them
///        in, the surface under a pixel, the pointer and the modifiers held, and the ways an edit
///        lands (a whole-model edit, a job of its own, a notice or an error).

#include "ui/jobs/job_runner.h"
#include "ui/jobs/model_edit.h"
#include "ui/sculpting/brush_options.h"
#include "ui/sculpting/surface_picker.h"
#include "ui/view/camera_control.h"
#include "ui/view/viewport.h"

#include <glm/vec2.hpp>
#include <openvdb/math/Mat4.h>

#include <optional>
#include <string>

namespace sculpt {
class Document;
}  // namespace sculpt

namespace sculpt::ui {
struct InputEvent;

class ToolHost {
public:
    virtual Document& document() = 0;
    virtual BrushOptions& brush() = 0;
    virtual const Viewport& viewport() const = 0;
    virtual const CameraControl& camera() const = 0;
    /// The picker the hover uses: a stroke freezes its box while it runs.
    virtual SurfacePicker& picker() = 0;
    /// The sculpted piece's surface under the pixel, in its field's world (where edits are made).
    virtual std::optional<SurfaceHit> pickAt(double x, double y) = 0;
    /// A hit of pickAt in the world (the piece's placement applied).
    virtual SurfaceHit inWorld(const SurfaceHit& hit) const = 0;
    /// The pointer, in window pixels.
    virtual glm::dvec2 pointer() const = 0;
    /// The modifier keys held down now.
    virtual int heldMods() const = 0;

    /// Why an edit of the document must wait (a job runs, a mode is open, a gesture), or "".
    virtual std::string waitReason() const = 0;
    /// True (saying why in the status bar) if an edit of the document must wait.
    virtual bool busy() = 0;
    virtual void notify(std::string notice) = 0;
    virtual void showError(const std::string& message) = 0;
    /// A recovery copy now, before a job that reads the model.
    virtual void autosaveNow() = 0;
    /// Runs `edit` on a copy of the model as a job; it lands as one undo step.
    virtual void startEdit(ModelEdit edit) = 0;
    /// The window's one job, for edits that land otherwise (pieces made or moved).
    virtual JobRunner& jobs() = 0;
    /// Draws the sculpted piece at `placement` (a gesture under way), not where the document has it.
    virtual void showPlacement(const openvdb::Mat4d& placement) = 0;
    /// `event` changed the model by `stamps` stamps: the frames measure when it is on screen.
    virtual void awaitFrame(const InputEvent& event, std::size_t stamps) = 0;

protected:
    ~ToolHost() = default;
};

/// Runs `work` (Progress -> Result) as the window's job, saying so; `land` (Result) takes its
/// result on the UI thread once it succeeded.
template <typename Result, typename WorkFn, typename LandFn>
void startJob(ToolHost& host, std::string label, WorkFn work, LandFn land)
{
    host.notify(label + "...");
    host.jobs().start<Result>(std::move(label), std::move(work), std::move(land));
}

}  // namespace sculpt::ui
