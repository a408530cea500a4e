// SPDX-License-Identifier: Apache-2.0
#include "ui/modes/primitives_mode.h"

#include "core/base/atomic_file.h"
#include "core/primitives/scene_file.h"
#include "sculpt/session/scene_bake.h"
#include "ui/input/input_event.h"
#include "ui/modes/mode_slot.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"
#include "ui/sculpting/surface_picker.h"
#include "ui/view/surface_look.h"

#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

namespace sculpt::ui {

namespace {

/// The Primitives panel, opened if it is not.
PrimitivesMode& opened(ModeSlot& slot)
{
    if (!slot.as<PrimitivesMode>()) {
        DocumentView& view = slot.host().view();
        slot.open(std::make_unique<PrimitivesMode>(view.viewport().renderer(), view.viewport().overlay(), view.look(),
                                                   slot.host().document().session().field().grid().transform().copy()));
    }
    return *slot.as<PrimitivesMode>();
}

}  // namespace

void PrimitivesMode::addCommands(CommandRegistry& commands, ModeSlot& slot)
{
    Workspace& work = slot.host().workspace();
    Dialogs& dialogs = slot.host().dialogs();
    const auto primitivesOrIdle = [&slot, &work] {
        return slot.as<PrimitivesMode>() ? std::string() : work.waitReason();
    };
    const auto placing = [&slot] {
        return slot.as<PrimitivesMode>() ? std::string()
                                         : std::string("no primitives are being placed: Shift+A adds one");
    };
    commands.add({Command::AddPrimitive,
                  "Add Primitive",
                  "Opens the Primitives panel and adds a blob where the pointer is on the surface (click or drag to "
                  "place it)",
                  {{GLFW_KEY_A, kShift}},
                  primitivesOrIdle,
                  [&slot] { addAtPointer(slot.host(), opened(slot).draft(), SkeletonType::Point); }});
    commands.add({Command::RemovePrimitive,
                  "Remove Primitive",
                  "Removes the selected primitive (Primitives panel)",
                  {{GLFW_KEY_DELETE}},
                  placing,
                  [&slot] { slot.as<PrimitivesMode>()->draft().removeSelected(); }});
    commands.add({Command::BakePrimitives,
                  "Bake Primitives",
                  "Combines the panel's primitives into the model by the scene's operation (one undo step)",
                  {},
                  [&work, placing] { return work.jobs().running() ? work.waitReason() : placing(); },
                  [&slot] { slot.accept(); }});
    commands.add({Command::LoadScene,
                  "Load Scene...",
                  "Opens a primitive scene file in the Primitives panel",
                  {{GLFW_KEY_O, kControl | kAlt}},
                  primitivesOrIdle,
                  [&slot, &dialogs] {
                      dialogs.ask(Prompt::Kind::LoadScene, {}, [&slot](const std::filesystem::path& path) {
                          const Scene scene = readScene(path);  // an error leaves the panel as it was
                          opened(slot).draft().load(scene);
                          slot.host().notices().say("loaded " + path.string() +
                                                    ": Enter bakes it into the model, Esc discards it");
                      });
                  }});
    commands.add({Command::SaveScene,
                  "Save Scene...",
                  "Writes the panel's primitives as a scene file for `sculpt build`",
                  {{GLFW_KEY_S, kControl | kAlt}},
                  placing,
                  [&slot, &dialogs] {
                      dialogs.ask(Prompt::Kind::SaveScene, "scene.json", [&slot](const std::filesystem::path& path) {
                          if (PrimitivesMode* primitives = slot.as<PrimitivesMode>()) {
                              writeFileAtomically(path, writeScene(primitives->draft().scene()));
                              slot.host().notices().say("saved the scene to " + path.string());
                          }
                      });
                  }});
}

void PrimitivesMode::addAtPointer(PanelHost& host, PrimitiveDraft& draft, SkeletonType type)
{
    const std::optional<SurfaceHit> hit = host.hitUnderPointer();
    const glm::dvec3 at = hit ? hit->position : host.camera().focalPoint();
    // A soft object crosses iso 0.5 near half its reach: twice the brush gives a blob its size.
    draft.add(type, {at.x, at.y, at.z}, 2.0 * host.brush().radius);
}

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

bool PrimitivesMode::accept(PanelHost& host)
{
    // Through the scene file's text: the bake is then `sculpt build` of the scene Save writes.
    const Scene scene = parseScene(writeScene(mDraft.scene()), "the scene");  // an error keeps the panel open
    host.workspace().startEdit({"bake " + std::to_string(scene.primitives.primitives().size()) + " primitives",
                                [scene](FieldImage model, const Progress& p) {
                                    return bakeScene(std::move(model), scene, "the scene", "the model", p);
                                },
                                {}});
    return true;
}

nlohmann::json PrimitivesMode::report()
{
    return {{"count", mDraft.primitives.size()},
            {"selected", mDraft.selected},
            {"problem", mDraft.problem()},
            {"preview_triangles", mPreview.triangleCount()}};
}

}  // namespace sculpt::ui
