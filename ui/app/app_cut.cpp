// SculptApp: the cut tools. A box, lasso or line drawn on the screen is swept along the view into
// a prism that cuts through the model (Ctrl: fills it with clay), or masks the clay it covers
// (Ctrl: unmasks), all the way or a slab from the surface under the gesture's first point;
// mirrored by the brush's symmetry; a job that lands as one undo step and in the stroke log (Save
// Strokes replays it). And the drain hole drilled where the pointer is.

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
    const bool ctrl = (mCutMods & kControl) != 0, fill = ctrl && !mGestureMasks;
    // A fill needs a depth: twice the brush's radius unless one is set.
    const double depth = mCutDepth > 0.0 ? mCutDepth : fill ? 2.0 * mBrush.radius : 0.0;
    const double nearDepth = depth > 0.0 ? mCutNear : -std::numeric_limits<double>::infinity();
    const double farDepth = depth > 0.0 ? mCutNear + depth : std::numeric_limits<double>::infinity();
    std::optional<ViewPrism> prism = mCut.prism(mViewport, nearDepth, farDepth, mBrush.symmetry);
    mCut.clear();
    if (!prism || busy()) return;
    // The piece's voxels are in its own world: view from it = view from the world after its placement.
    prism->viewFromWorld = mDocument->pieces()[mDocument->activePiece()].look.placement * prism->viewFromWorld;
    const std::string slab = depth > 0.0 ? " (slab)" : "";
    if (mGestureMasks) {
        MaskSelection selection;
        selection.prism = *prism;
        selection.erase = ctrl;
        const char* shape = mCut.shape() == CutGesture::Shape::Box ? " box" : " lasso";
        return selectMask(selection, std::string(ctrl ? "unmask" : "mask") + shape + slab);
    }
    ScriptEvent event;
    event.kind = ScriptEvent::Kind::Cut;
    event.prism = *prism;
    event.prismMode = fill ? PrismMode::Fill : PrismMode::Cut;
    const std::string label = std::string(fill ? "fill" : "cut") + slab;
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
    const bool ctrl = ((mCutMods | mHeldMods) & kControl) != 0;
    const ImU32 colour = mGestureMasks ? (ctrl ? IM_COL32(230, 230, 230, 230) : IM_COL32(90, 90, 110, 230))
                         : ctrl        ? IM_COL32(140, 220, 140, 230)
                                       : IM_COL32(255, 120, 100, 230);
    const bool closed = mCut.shape() != CutGesture::Shape::Line;
    ImGui::GetForegroundDrawList()->AddPolyline(points.data(), int(points.size()), colour,
                                                closed ? ImDrawFlags_Closed : ImDrawFlags_None, 2.0f);
}

void SculptApp::drillDrainHoleUnderPointer()
{
    if (busy()) return;
    const std::optional<SurfaceHit> hit = pickAt(mMouseX, mMouseY);
    if (!hit) return notify("point at the wall to drill the drain hole through first");
    const FieldImage& field = mDocument->session().field();
    const openvdb::Vec3d at(hit->position.x, hit->position.y, hit->position.z);
    const openvdb::Vec3d normal(hit->normal.x, hit->normal.y, hit->normal.z);
    const double radius = mDialogs.filter.drainRadiusWorld;
    const double farthest = std::max(mDocument->session().modelSize(), 4.0 * field.voxelSize());
    const std::optional<DrainHole> hole = drainHoleAt(field, at, normal, radius, farthest);
    if (!hole) return notify("no hollow behind the wall here: Filters > Hollow makes one");
    mDocument->drillHoles({*hole});
    mDialogs.notice = "drain hole drilled (Ctrl+Z undoes it)";
}

}  // namespace sculpt::ui
