// SculptApp: the one mode that may own the view (import, primitives, morph frames), opened,
// accepted and closed here whatever it is.

#include "core/base/errors.h"
#include "core/primitives/scene_file.h"
#include "ui/app/sculpt_app.h"
#include "ui/modes/primitives_mode.h"

namespace sculpt::ui {

void SculptApp::openMode(std::unique_ptr<Mode> mode)
{
    closeMode();
    mMode = std::move(mode);
    mDialogs.notice = mMode->hint();
}

void SculptApp::closeMode()
{
    if (!mMode) return;
    // Its hint, or why edits waited for it, would mislead once it is gone.
    if (mDialogs.notice == mMode->hint() || mDialogs.notice == mMode->waitNotice()) mDialogs.notice.clear();
    if (mDrag == Drag::Mode) mDrag = Drag::None;
    mMode.reset();
}

void SculptApp::acceptMode()
{
    if (!mMode || mJobs.running()) return;
    try {
        if (mMode->accept(*this)) closeMode();
    } catch (const InputError& e) {  // the mode stays open, as it was
        showError(e.what());
    }
}

void SculptApp::drawModePanel()
{
    if (mMode) mMode->drawPanel(*this);
}

PrimitivesMode& SculptApp::primitivesMode()
{
    if (!mode<PrimitivesMode>()) {
        openMode(std::make_unique<PrimitivesMode>(mView.viewport().renderer(), mView.viewport().overlay(), mView.look(),
                                                  mDocument->session().field().grid().transform().copy()));
    }
    return *mode<PrimitivesMode>();
}

void SculptApp::addPrimitive(SkeletonType type)
{
    if (!mode<PrimitivesMode>() && busy()) return;
    const std::optional<SurfaceHit> hit = pickAt(mPointer.x(), mPointer.y());
    const glm::dvec3 at = hit ? hit->position : mView.camera().focalPoint();
    // A soft object crosses iso 0.5 near half its reach: twice the brush gives a blob its size.
    primitivesMode().draft().add(type, {at.x, at.y, at.z}, 2.0 * mBrush.radius);
}

void SculptApp::loadScene(const std::filesystem::path& path)
{
    const Scene scene = readScene(path);  // an error leaves the panel as it was
    primitivesMode().draft().load(scene);
    mDialogs.notice = "loaded " + path.string() + ": Enter bakes it into the model, Esc discards it";
}

}  // namespace sculpt::ui
