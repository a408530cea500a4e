#pragma once
/// @file primitives_mode.h
/// @brief Placing primitives (Shift+A, Primitives > Load Scene): the Primitives panel, their
///        skeletons and blended surface on screen over see-through clay; a click or drag on the
///        surface moves the selected one. Enter bakes them into the model as one undo step.

#include "ui/document/primitive_draft.h"
#include "ui/modes/mode.h"
#include "ui/view/shape_display.h"
#include "ui/view/skeleton_display.h"

namespace sculpt::ui {

class SurfaceLook;

class PrimitivesMode final : public Mode {
public:
    /// Previews on `voxels` (the document's lattice); the clay is see-through while it is open.
    PrimitivesMode(vtkRenderer* scene, vtkRenderer* overlay, SurfaceLook& look,
                   openvdb::math::Transform::ConstPtr voxels);
    ~PrimitivesMode() override;

    PrimitiveDraft& draft() { return mDraft; }

    const char* name() const override { return "primitives"; }
    std::string waitNotice() const override;
    std::string hint() const override;
    bool sync(double now) override;
    bool press(const SurfaceHit& hit) override;
    void drag(const SurfaceHit& hit) override;
    bool accept(ModeHost& host) override;
    void drawPanel(SculptApp& app) override;
    nlohmann::json report() override;

private:
    SurfaceLook& mLook;
    PrimitiveDraft mDraft;
    ShapeDisplay mPreview;
    SkeletonDisplay mSkeletons;
    int mSkeletonsSelected = -1;  // the selection the skeletons were last drawn with
};

}  // namespace sculpt::ui
