// SPDX-License-Identifier: Apache-2.0
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

class CommandRegistry;
class ModeSlot;
class PanelHost;
class SurfaceLook;

class PrimitivesMode final : public Mode {
public:
    /// Add Primitive (opening this mode in `slot`), Remove, Bake, Load and Save Scene.
    static void addCommands(CommandRegistry& commands, ModeSlot& slot);
    /// Adds a primitive of `type` to `draft` where the pointer is on the surface (else at the
    /// view's centre), as large as the brush.
    static void addAtPointer(PanelHost& host, PrimitiveDraft& draft, SkeletonType type);

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
    bool accept(PanelHost& host) override;
    void drawPanel(PanelHost& host) override;
    nlohmann::json report() override;

private:
    SurfaceLook& mLook;
    PrimitiveDraft mDraft;
    ShapeDisplay mPreview;
    SkeletonDisplay mSkeletons;
    int mSkeletonsSelected = -1;  // the selection the skeletons were last drawn with
};

}  // namespace sculpt::ui
