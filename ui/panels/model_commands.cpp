// SPDX-License-Identifier: Apache-2.0
// The Filters and Mask menus' commands: whole-model filters (each a dialog, then a job), the
// island and drain hole under the pointer, and the mask's operations and selections. Each lands
// through the workspace as one undo step.

#include "core/base/errors.h"
#include "core/solids/hollow.h"
#include "core/solids/islands.h"
#include "ui/input/input_event.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace sculpt::ui {

namespace {

void startFilter(Workspace& work, const ModelFilter& filter)
{
    if (work.busy()) return;
    const std::string source =
        work.document().path().empty() ? std::string("the model") : work.document().path().string();
    work.startEdit({filterLabel(filter),
                    [filter, source](FieldImage model, const Progress& p) {
                        return applyFilter(std::move(model), filter, source, p);
                    },
                    {}});
}

/// Keeps only (or deletes) the island under the pointer, as a job; says so when none is there.
void editIslandUnderPointer(PanelHost& host, bool keep)
{
    Workspace& work = host.workspace();
    if (work.busy()) return;
    const std::optional<SurfaceHit> hit = host.hitUnderPointer();
    if (!hit) return host.notices().say(std::string("point at the island to ") + (keep ? "keep" : "delete") + " first");
    const openvdb::Vec3d at(hit->position.x, hit->position.y, hit->position.z);
    const double reach = 2.0 * work.document().session().field().voxelSize();
    const char* label = keep ? "keep island" : "delete island";
    work.startEdit({label,
                    [at, reach, keep, label](FieldImage model, const Progress&) {
                        const std::vector<Island> islands = findIslands(model);
                        const int index = islandAt(islands, at, reach);
                        if (index < 0) throw InputError("no island under the pointer");
                        keepOrRemoveIsland(model, islands, std::size_t(index), keep);
                        refuseEmptyResult(model, "the model", label);
                        return model;
                    },
                    {}});
}

/// Drills a drain hole at the pointer through the wall to the hollow behind it, one undo step
/// (radius: the Hollow dialog's); says so when no hollow lies behind.
void drillDrainHoleUnderPointer(PanelHost& host)
{
    Workspace& work = host.workspace();
    if (work.busy()) return;
    const std::optional<SurfaceHit> hit = host.hitUnderPointer();
    if (!hit) return host.notices().say("point at the wall to drill the drain hole through first");
    const FieldImage& field = work.document().session().field();
    const openvdb::Vec3d at(hit->position.x, hit->position.y, hit->position.z);
    const openvdb::Vec3d normal(hit->normal.x, hit->normal.y, hit->normal.z);
    const double radius = host.dialogs().filter.drainRadiusWorld;
    const double farthest = std::max(work.document().session().modelSize(), 4.0 * field.voxelSize());
    const std::optional<DrainHole> hole = drainHoleAt(field, at, normal, radius, farthest);
    if (!hole) return host.notices().say("no hollow behind the wall here: Filters > Hollow makes one");
    work.document().drillHoles({*hole});
    work.landed("drill drain hole");
}

/// A mask operation on the sculpted piece, one undo step (the status bar says when it changed nothing).
void editMask(Workspace& work, MaskOperation operation)
{
    if (work.busy() || work.document().editMask(operation)) return;
    work.notices().say(work.document().session().field().mask()
                           ? "the mask did not change"
                           : "nothing is masked: paint a mask first (M), or invert to mask everything");
}

void addFilterCommands(CommandRegistry& commands, PanelHost& host)
{
    Workspace& work = host.workspace();
    const auto idle = [&work] { return work.waitReason(); };
    struct Filter {
        Command command;
        const char* label;
        const char* help;
        std::vector<Chord> chords;
        ModelFilter::Kind kind;
        Prompt::Kind prompt;
    };
    const Filter filters[] = {
        {Command::SmoothModel,
         "Smooth Model...",
         "Mean-curvature flow over the whole model, as a job (Esc cancels; one undo step)",
         {{GLFW_KEY_S, kAlt}},
         ModelFilter::Kind::Smooth,
         Prompt::Kind::SmoothModel},
        {Command::OffsetModel,
         "Offset Model...",
         "Grow or shrink the whole model along its normal, as a job (Esc cancels; one undo step)",
         {{GLFW_KEY_O, kAlt}},
         ModelFilter::Kind::Offset,
         Prompt::Kind::OffsetModel},
        {Command::HollowModel,
         "Hollow...",
         "Make the model a shell of a wall thickness with drain holes (for resin prints), as a job",
         {},
         ModelFilter::Kind::Hollow,
         Prompt::Kind::HollowModel},
        {Command::RemoveIslands,
         "Remove Small Islands...",
         "Remove the disjoint bits of clay (a scan's specks) under a volume, as a job",
         {},
         ModelFilter::Kind::RemoveIslands,
         Prompt::Kind::RemoveIslands},
    };
    for (const Filter& f : filters) {
        commands.add({f.command, f.label, f.help, f.chords, idle, [&host, &work, kind = f.kind, prompt = f.prompt] {
                          Dialogs& dialogs = host.dialogs();
                          dialogs.filter.kind = kind;
                          dialogs.ask(prompt, dialogs.prompt.path, [&work, &dialogs](const std::filesystem::path&) {
                              startFilter(work, dialogs.filter);
                          });
                      }});
    }
    commands.add({Command::KeepIsland,
                  "Keep Island",
                  "Keeps only the island (disjoint bit of clay) under the pointer, as a job",
                  {{GLFW_KEY_L, kShift}},
                  idle,
                  [&host] { editIslandUnderPointer(host, true); }});
    commands.add({Command::DeleteIsland,
                  "Delete Island",
                  "Deletes the island (disjoint bit of clay) under the pointer, as a job",
                  {{GLFW_KEY_L, kAlt}},
                  idle,
                  [&host] { editIslandUnderPointer(host, false); }});
    commands.add({Command::DrillDrainHole,
                  "Drill Drain Hole",
                  "Drills a drain hole at the pointer, straight in through the wall to the hollow behind it (radius: "
                  "Filters > Hollow's hole radius)",
                  {{GLFW_KEY_H, kControl}},
                  idle,
                  [&host] { drillDrainHoleUnderPointer(host); }});
}

void addMaskCommands(CommandRegistry& commands, PanelHost& host)
{
    Workspace& work = host.workspace();
    const auto idle = [&work] { return work.waitReason(); };
    struct Operation {
        Command command;
        const char* label;
        const char* help;
        std::vector<Chord> chords;
        MaskOperation operation;
    };
    const Operation operations[] = {
        {Command::InvertMask,
         "Invert Mask",
         "Masked clay becomes free, free clay masked",
         {{GLFW_KEY_I, kControl | kShift}},
         MaskOperation::Invert},
        {Command::ClearMask,
         "Clear Mask",
         "Frees the whole model",
         {{GLFW_KEY_M, kControl | kShift}},
         MaskOperation::Clear},
        {Command::BlurMask, "Blur Mask", "Softens the mask's edge by a voxel", {}, MaskOperation::Blur},
        {Command::SharpenMask, "Sharpen Mask", "Crisps the mask's edge", {}, MaskOperation::Sharpen},
        {Command::GrowMask, "Grow Mask", "Spreads the mask by a voxel", {}, MaskOperation::Grow},
        {Command::ShrinkMask, "Shrink Mask", "Draws the mask back by a voxel", {}, MaskOperation::Shrink},
    };
    for (const Operation& o : operations)
        commands.add({o.command, o.label, o.help, o.chords, idle,
                      [&work, operation = o.operation] { editMask(work, operation); }});
    const auto select = [&work](MaskSelection selection, const char* label) {
        work.startEdit(maskSelectionEdit(selection, label));
    };
    commands.add({Command::MaskIsland,
                  "Mask Island",
                  "Masks the island (disjoint bit of clay) under the pointer, as a job",
                  {{GLFW_KEY_L, kControl}},
                  idle,
                  [&host, select] {
                      const std::optional<SurfaceHit> hit = host.hitUnderPointer();
                      if (!hit) return host.notices().say("point at the island to mask first");
                      MaskSelection selection;
                      selection.kind = MaskSelectionKind::Island;
                      selection.point = openvdb::Vec3d(hit->position.x, hit->position.y, hit->position.z);
                      select(selection, "mask island");
                  }});
    commands.add({Command::MaskCavities,
                  "Mask Cavities",
                  "Masks the creases and hollows, where the surface curves inwards (fully within the crease "
                  "radius), as a job",
                  {},
                  idle,
                  [&host, select] {
                      MaskSelection selection;
                      selection.kind = MaskSelectionKind::Cavity;
                      const double voxel = host.document().session().field().voxelSize();
                      const double radius = host.dialogs().creaseRadius;
                      selection.creaseRadiusWorld = radius > 0.0 ? radius : 4.0 * voxel;
                      select(selection, "mask cavities");
                  }});
    commands.add({Command::MaskThinWalls,
                  "Mask Thin Walls",
                  "Masks the walls thinner than the thickness set here (View > Print Check shows them red), as a job",
                  {},
                  idle,
                  [&host, select] {
                      MaskSelection selection;
                      selection.kind = MaskSelectionKind::Thin;
                      selection.thicknessWorld = host.view().printCheck().thinnerThan;
                      select(selection, "mask thin walls");
                  }});
}

}  // namespace

void addModelCommands(CommandRegistry& commands, PanelHost& host)
{
    addFilterCommands(commands, host);
    addMaskCommands(commands, host);
}

}  // namespace sculpt::ui
