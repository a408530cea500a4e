// SculptApp: the cut tools. A box, lasso or line drawn on the screen is swept along the view into
// a prism that cuts through the model (Ctrl: fills it with clay), all the way or a slab from the
// surface under the gesture's first point; mirrored by the brush's symmetry; a job that lands as
// one undo step and in the stroke log (Save Strokes replays it).

#include "sculpt/session/model_filter.h"
#include "ui/app/sculpt_app.h"

#include <imgui.h>

#include <cmath>
#include <limits>

namespace sculpt::ui {

void SculptApp::beginCut(const InputEvent& event)
{
    mCutMods = event.mods | mHeldMods;
    const glm::dmat4 view = mViewport.viewFromWorld();
    const std::optional<SurfaceHit> hit = pickAt(mMouseX, mMouseY);
    const glm::dvec3 at = hit ? inWorld(*hit).position : mCamera.focalPoint();
    mCutNear = -(view * glm::dvec4(at, 1.0)).z;
    mCut.begin(*mCutTool, mMouseX, mMouseY);
    mDrag = Drag::Cut;
}

void SculptApp::finishCut()
{
    const bool fill = (mCutMods & kControl) != 0;
    // A fill needs a depth: twice the brush's radius unless one is set.
    const double depth = mCutDepth > 0.0 ? mCutDepth : fill ? 2.0 * mBrush.radius : 0.0;
    const double nearDepth = depth > 0.0 ? mCutNear : -std::numeric_limits<double>::infinity();
    const double farDepth = depth > 0.0 ? mCutNear + depth : std::numeric_limits<double>::infinity();
    const std::optional<ViewPrism> prism = mCut.prism(mViewport, nearDepth, farDepth, mBrush.symmetry);
    mCut.clear();
    if (!prism || busy()) return;
    const PrismMode mode = fill ? PrismMode::Fill : PrismMode::Cut;
    ScriptEvent event;
    event.kind = ScriptEvent::Kind::Cut;
    event.prism = *prism;
    // The piece's voxels are in its own world: view from it = view from the world after its placement.
    event.prism.viewFromWorld = mDocument->pieces()[mDocument->activePiece()].look.placement * prism->viewFromWorld;
    event.prismMode = mode;
    const std::string label = std::string(fill ? "fill" : "cut") + (depth > 0.0 ? " (slab)" : "");
    autosaveNow();
    auto copy = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
    startJob<FieldImage>(
        label,
        [copy, event, label](const Progress&) {
            FieldImage result = applyPrism(*copy, event.prism, event.prismMode);
            refuseEmptyResult(result, "the model", label);
            return result;
        },
        [this, label, event](FieldImage result) {
            mDocument->replaceField(std::move(result), label, event);
            mDialogs.notice = label + " done (Ctrl+Z undoes it)";
        });
}

void SculptApp::drawCutOutline() const
{
    if (!mCut.active()) return;
    const std::vector<glm::dvec2> outline = mCut.outline();
    std::vector<ImVec2> points;
    for (const glm::dvec2& p : outline) points.emplace_back(float(p.x), float(p.y));
    const bool fill = ((mCutMods | mHeldMods) & kControl) != 0;
    const ImU32 colour = fill ? IM_COL32(140, 220, 140, 230) : IM_COL32(255, 120, 100, 230);
    const bool closed = mCut.shape() != CutGesture::Shape::Line;
    ImGui::GetForegroundDrawList()->AddPolyline(points.data(), int(points.size()), colour,
                                                closed ? ImDrawFlags_Closed : ImDrawFlags_None, 2.0f);
}

}  // namespace sculpt::ui
