// SculptApp: mask selections, the mask made at once from what a rule selects (a box or lasso
// gesture's prism, the island under the pointer, the cavities, the thin walls). Each is worked
// out on a copy of the model off the UI thread and lands as one undo step holding the mask whole,
// in the stroke log (Save Strokes replays it through the session's journalled path).

#include "ui/app/sculpt_app.h"

namespace sculpt::ui {

void SculptApp::selectMask(const MaskSelection& selection, const std::string& label)
{
    if (busy()) return;
    auto copy = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
    startJob<openvdb::FloatGrid::Ptr>(
        label,
        [copy, selection](const Progress&) {
            applyMaskSelection(*copy, selection, nullptr);
            return copy->maskPtr();
        },
        [this, label, selection](openvdb::FloatGrid::Ptr mask) {
            ScriptEvent event;
            event.kind = ScriptEvent::Kind::MaskSelection;
            event.maskSelection = selection;
            mDocument->replaceMask(std::move(mask), label, event);
            mDialogs.notice = label + " done (Ctrl+Z undoes it)";
        });
}

void SculptApp::maskIslandUnderPointer()
{
    const std::optional<SurfaceHit> hit = pickAt(mMouseX, mMouseY);
    if (!hit) return notify("point at the island to mask first");
    MaskSelection selection;
    selection.kind = MaskSelectionKind::Island;
    selection.point = openvdb::Vec3d(hit->position.x, hit->position.y, hit->position.z);
    selectMask(selection, "mask island");
}

void SculptApp::maskCavities()
{
    MaskSelection selection;
    selection.kind = MaskSelectionKind::Cavity;
    selection.creaseRadiusWorld = mCreaseRadius > 0.0 ? mCreaseRadius : 4.0 * mDocument->session().field().voxelSize();
    selectMask(selection, "mask cavities");
}

void SculptApp::maskThinWalls()
{
    MaskSelection selection;
    selection.kind = MaskSelectionKind::Thin;
    selection.thicknessWorld = mCheck.thinnerThan;
    selectMask(selection, "mask thin walls");
}

}  // namespace sculpt::ui
