#include "ui/modes/primitives_mode.h"

#include "core/primitives/scene_file.h"
#include "sculpt/session/scene_bake.h"
#include "ui/modes/mode_host.h"
#include "ui/panels/panels.h"
#include "ui/sculpting/surface_picker.h"
#include "ui/view/surface_look.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

PrimitivesMode::PrimitivesMode(vtkRenderer* scene, vtkRenderer* overlay, SurfaceLook& look,
                               openvdb::math::Transform::ConstPtr voxels)
    : mLook(look), mDraft(std::move(voxels)), mPreview(scene, ShapeStyle::primitives()), mSkeletons(overlay)
{
    mLook.setXRay(true);
}

PrimitivesMode::~PrimitivesMode() { mLook.setXRay(false); }

std::string PrimitivesMode::waitNotice() const
{
    return "primitives are being placed: bake them (Enter) or discard them (Esc) first";
}

std::string PrimitivesMode::hint() const
{
    return "click or drag on the surface to place it; Enter bakes, Esc discards";
}

bool PrimitivesMode::sync(double /*now*/)
{
    const bool changed = mDraft.refresh();
    if (changed) mPreview.set(mDraft.preview());
    // The skeletons' geometry is rebuilt only when the scene or the selection changed.
    if (changed || mDraft.selected != mSkeletonsSelected) mSkeletons.show(mDraft.primitives, mDraft.selected);
    mSkeletonsSelected = mDraft.selected;
    return changed;
}

bool PrimitivesMode::press(const SurfaceHit& hit)
{
    drag(hit);
    return true;
}

void PrimitivesMode::drag(const SurfaceHit& hit)
{
    mDraft.moveSelectedTo({hit.position.x, hit.position.y, hit.position.z});
}

bool PrimitivesMode::accept(ModeHost& host)
{
    // Through the scene file's text: the bake is then `sculpt build` of the scene Save writes.
    const Scene scene = parseScene(writeScene(mDraft.scene()), "the scene");  // an error keeps the panel open
    host.startEdit({"bake " + std::to_string(scene.primitives.primitives().size()) + " primitives",
                    [scene](FieldImage model, const Progress& p) {
                        return bakeScene(std::move(model), scene, "the scene", "the model", p);
                    },
                    {}});
    return true;
}

void PrimitivesMode::drawPanel(SculptApp& app) { drawPrimitivesPanel(app, mDraft); }

nlohmann::json PrimitivesMode::report()
{
    return {{"count", mDraft.primitives.size()},
            {"selected", mDraft.selected},
            {"problem", mDraft.problem()},
            {"preview_triangles", mPreview.triangleCount()}};
}

}  // namespace sculpt::ui
