#include "ui/app/sculpt_app.h"
#include "ui/panels/panels.h"

#include <imgui.h>

#include <algorithm>

namespace sculpt::ui {

void commandMenuItem(SculptApp& app, Command command)
{
    const std::string keys = app.commands().shortcutText(command);
    const bool enabled = app.whyNot(command).empty();  // the rule execute() checks
    if (ImGui::MenuItem(app.commands().row(command).label, keys.empty() ? nullptr : keys.c_str(), false, enabled))
        app.execute(command);
    commandTooltip(app, command);
}

void commandButton(SculptApp& app, Command command)
{
    const bool enabled = app.whyNot(command).empty();
    if (!enabled) ImGui::BeginDisabled();
    if (ImGui::Button(app.commands().row(command).label)) app.execute(command);
    if (!enabled) ImGui::EndDisabled();
    commandTooltip(app, command);
}

void commandTooltip(const SculptApp& app, Command command)
{
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    const std::string keys = app.commands().shortcutText(command), blocked = app.whyNot(command);
    ImGui::SetTooltip("%s%s%s%s%s", app.commands().row(command).help, keys.empty() ? "" : "\nKey: ", keys.c_str(),
                      blocked.empty() ? "" : "\nNot now: ", blocked.c_str());
}

namespace {

/// View > Print Check: colour thin walls or overhangs, with their thresholds.
/// The wall thickness under which the print check flags (and Mask Thin Walls masks).
void thicknessField(SurfaceTint& check, const char* tooltip)
{
    ImGui::SetNextItemWidth(120);
    if (ImGui::InputDouble("thinner than", &check.thinnerThan, 0.1, 1.0, "%.3g"))
        check.thinnerThan = std::max(check.thinnerThan, 1e-3);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
}

void printCheckMenu(SurfaceTint& check)
{
    if (!ImGui::BeginMenu("Print Check")) return;
    for (SurfaceTint::Check c : {SurfaceTint::Check::None, SurfaceTint::Check::Thickness, SurfaceTint::Check::Overhang})
        if (ImGui::MenuItem(checkName(c), nullptr, check.check == c)) check.check = c;
    ImGui::Separator();
    thicknessField(check, "Walls thinner than this (world units) show red");
    ImGui::SetNextItemWidth(120);
    if (ImGui::InputDouble("steeper than", &check.steeperThan, 1.0, 5.0, "%.3g"))
        check.steeperThan = std::clamp(check.steeperThan, 1.0, 89.0);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Faces overhanging closer to facing down than this (degrees; print direction +z) show blue");
    ImGui::EndMenu();
}

/// The mask selections and their settings: a crease radius (0: four voxels) and the print
/// check's thickness threshold.
void selectionItems(SculptApp& app)
{
    commandMenuItem(app, Command::MaskIsland);
    commandMenuItem(app, Command::MaskCavities);
    ImGui::SetNextItemWidth(120);
    if (ImGui::InputDouble("crease radius", &app.creaseRadius(), 0.1, 1.0,
                           app.creaseRadius() > 0.0 ? "%.3g" : "4 voxels"))
        app.creaseRadius() = std::max(app.creaseRadius(), 0.0);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Creases curving inwards this tightly or more are masked fully, wider ones in part");
    commandMenuItem(app, Command::MaskThinWalls);
    thicknessField(app.printCheck(), "Walls thinner than this (world units) are masked (and show red in the "
                                     "print check)");
}

}  // namespace

void drawMainMenu(SculptApp& app)
{
    if (!ImGui::BeginMainMenuBar()) return;
    const auto item = [&app](Command c) { commandMenuItem(app, c); };
    if (ImGui::BeginMenu("File")) {
        item(Command::New);
        item(Command::Open);
        if (ImGui::BeginMenu("Open Recent", !app.recent().entries().empty())) {
            for (const auto& path : app.recent().entries()) {
                if (ImGui::MenuItem(path.string().c_str())) app.openRecent(path);
            }
            ImGui::EndMenu();
        }
        item(Command::Import);
        ImGui::Separator();
        item(Command::Save);
        item(Command::SaveAs);
        item(Command::ExportMesh);
        item(Command::SaveStrokes);
        ImGui::Separator();
        item(Command::LoadTarget);
        ImGui::Separator();
        item(Command::Quit);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        item(Command::Undo);
        item(Command::Redo);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Primitives")) {
        item(Command::AddPrimitive);
        item(Command::RemovePrimitive);
        item(Command::BakePrimitives);
        ImGui::Separator();
        item(Command::LoadScene);
        item(Command::SaveScene);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Mask")) {
        for (Command c : {Command::ToolMask, Command::ToolBoxMask, Command::ToolLassoMask}) item(c);
        ImGui::Separator();
        for (Command c : {Command::InvertMask, Command::ClearMask, Command::BlurMask, Command::SharpenMask,
                          Command::GrowMask, Command::ShrinkMask})
            item(c);
        ImGui::Separator();
        selectionItems(app);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Filters")) {
        item(Command::SmoothModel);
        item(Command::OffsetModel);
        item(Command::HollowModel);
        item(Command::DrillDrainHole);
        item(Command::RemoveIslands);
        item(Command::KeepIsland);
        item(Command::DeleteIsland);
        ImGui::Separator();
        item(Command::MorphTo);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        for (int s = 0; s < 4; ++s) {
            if (ImGui::MenuItem(kShadingNames[s], nullptr, int(app.look().shading()) == s))
                app.look().setShading(Shading(s));
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Flat Shading", app.commands().shortcutText(Command::ToggleFlat).c_str(),
                            app.look().flat()))
            app.execute(Command::ToggleFlat);
        if (ImGui::MenuItem("Wireframe", app.commands().shortcutText(Command::ToggleWireframe).c_str(),
                            app.look().wireframe()))
            app.execute(Command::ToggleWireframe);
        if (ImGui::MenuItem("Scales", app.commands().shortcutText(Command::ToggleScales).c_str(), app.scalesShown()))
            app.execute(Command::ToggleScales);
        if (ImGui::MenuItem("X-Ray", app.commands().shortcutText(Command::ToggleXRay).c_str(), app.look().xray()))
            app.execute(Command::ToggleXRay);
        if (ImGui::MenuItem("Target Ghost", app.commands().shortcutText(Command::ToggleGhost).c_str(), app.ghostShown(),
                            app.whyNot(Command::ToggleGhost).empty()))
            app.execute(Command::ToggleGhost);
        if (ImGui::MenuItem("Trackball Orbit", app.commands().shortcutText(Command::ToggleTrackball).c_str(),
                            app.camera().trackball))
            app.execute(Command::ToggleTrackball);
        printCheckMenu(app.printCheck());
        ImGui::Separator();
        for (Command c : {Command::FrameModel, Command::ViewFront, Command::ViewBack, Command::ViewRight,
                          Command::ViewLeft, Command::ViewTop, Command::ViewBottom}) {
            item(c);
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        item(Command::ToggleHelp);
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

}  // namespace sculpt::ui
