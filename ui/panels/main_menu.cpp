// SPDX-License-Identifier: Apache-2.0
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

#include <algorithm>

namespace sculpt::ui {

void commandMenuItem(PanelHost& host, Command command)
{
    const std::string keys = host.commands().shortcutText(command);
    const bool enabled = host.whyNot(command).empty();  // the rule execute() checks
    if (ImGui::MenuItem(host.commands().row(command).label, keys.empty() ? nullptr : keys.c_str(), false, enabled))
        host.execute(command);
    commandTooltip(host, command);
}

void commandButton(PanelHost& host, Command command)
{
    const bool enabled = host.whyNot(command).empty();
    if (!enabled) ImGui::BeginDisabled();
    if (ImGui::Button(host.commands().row(command).label)) host.execute(command);
    if (!enabled) ImGui::EndDisabled();
    commandTooltip(host, command);
}

void commandTooltip(const PanelHost& host, Command command)
{
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    const std::string keys = host.commands().shortcutText(command), blocked = host.whyNot(command);
    ImGui::SetTooltip("%s%s%s%s%s", host.commands().row(command).help, keys.empty() ? "" : "\nKey: ", keys.c_str(),
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

/// View > Clip Plane: the axis, the side hidden, and where it cuts (a slider over the model).
void clipPlaneMenu(PanelHost& host)
{
    if (!ImGui::BeginMenu("Clip Plane")) return;
    ClipPlane& clip = host.view().clip();
    const openvdb::BBoxd box = host.view().worldBox(host.document());
    const openvdb::Vec3d centre = box.empty() ? openvdb::Vec3d(0.0) : box.getCenter();
    const Viewport& viewport = host.view().viewport();
    const glm::dvec3 ahead = viewport.rayThrough(0.5 * viewport.width(), 0.5 * viewport.height()).direction;
    for (int a = 0; a < 5; ++a) {
        const std::string shortcut = a == 0 ? host.commands().shortcutText(Command::CycleClipPlane) : std::string();
        if (ImGui::MenuItem(kClipAxisNames[a], shortcut.c_str(), int(clip.axis()) == a))
            clip.setAxis(ClipAxis(a), ahead, {centre.x(), centre.y(), centre.z()});
    }
    ImGui::Separator();
    if (const std::optional<SectionPlane> plane = clip.plane(); plane && !box.empty()) {
        double lo = 1e300, hi = -1e300;  // the model's extent along the normal
        for (int c = 0; c < 8; ++c) {
            const openvdb::Vec3d corner((c & 1) ? box.max().x() : box.min().x(),
                                        (c & 2) ? box.max().y() : box.min().y(),
                                        (c & 4) ? box.max().z() : box.min().z());
            const double along = corner.dot(clip.flipped() ? -plane->normal : plane->normal);
            lo = std::min(lo, along), hi = std::max(hi, along);
        }
        float offset = float(clip.offset());
        if (ImGui::SliderFloat("Position", &offset, float(lo), float(hi), "%.1f")) clip.setOffset(offset);
        if (ImGui::MenuItem("Flip Side", host.commands().shortcutText(Command::FlipClipPlane).c_str(), clip.flipped()))
            host.execute(Command::FlipClipPlane);
        ImGui::TextDisabled("Alt+Up / Alt+Down move it");
    } else {
        ImGui::TextDisabled("Off: choose an axis");
    }
    ImGui::EndMenu();
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
void selectionItems(PanelHost& host)
{
    commandMenuItem(host, Command::MaskIsland);
    commandMenuItem(host, Command::MaskCavities);
    ImGui::SetNextItemWidth(120);
    if (ImGui::InputDouble("crease radius", &host.dialogs().creaseRadius, 0.1, 1.0,
                           host.dialogs().creaseRadius > 0.0 ? "%.3g" : "4 voxels"))
        host.dialogs().creaseRadius = std::max(host.dialogs().creaseRadius, 0.0);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Creases curving inwards this tightly or more are masked fully, wider ones in part");
    commandMenuItem(host, Command::MaskThinWalls);
    thicknessField(host.view().printCheck(), "Walls thinner than this (world units) are masked (and show red in the "
                                             "print check)");
}

}  // namespace

void drawMainMenu(PanelHost& host)
{
    if (!ImGui::BeginMainMenuBar()) return;
    const auto item = [&host](Command c) { commandMenuItem(host, c); };
    if (ImGui::BeginMenu("File")) {
        item(Command::New);
        item(Command::Open);
        if (ImGui::BeginMenu("Open Recent", !host.files().recent().entries().empty())) {
            for (const auto& path : host.files().recent().entries()) {
                if (ImGui::MenuItem(path.string().c_str()) && host.files().guardUnsaved(Command::Open))
                    host.files().open(path);
            }
            ImGui::EndMenu();
        }
        item(Command::Import);
        ImGui::Separator();
        item(Command::Save);
        item(Command::SaveAs);
        item(Command::ExportMesh);
        item(Command::ExportLabels);
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
        selectionItems(host);
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
            if (ImGui::MenuItem(kShadingNames[s], nullptr, int(host.look().shading()) == s))
                host.look().setShading(Shading(s));
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Flat Shading", host.commands().shortcutText(Command::ToggleFlat).c_str(),
                            host.look().flat()))
            host.execute(Command::ToggleFlat);
        if (ImGui::MenuItem("Wireframe", host.commands().shortcutText(Command::ToggleWireframe).c_str(),
                            host.look().wireframe()))
            host.execute(Command::ToggleWireframe);
        if (ImGui::MenuItem("Scales", host.commands().shortcutText(Command::ToggleScales).c_str(),
                            host.view().scales().shown()))
            host.execute(Command::ToggleScales);
        if (ImGui::MenuItem("X-Ray", host.commands().shortcutText(Command::ToggleXRay).c_str(), host.look().xray()))
            host.execute(Command::ToggleXRay);
        if (ImGui::MenuItem("Target Ghost", host.commands().shortcutText(Command::ToggleGhost).c_str(),
                            host.view().ghost().shown(), host.whyNot(Command::ToggleGhost).empty()))
            host.execute(Command::ToggleGhost);
        if (ImGui::MenuItem("Trackball Orbit", host.commands().shortcutText(Command::ToggleTrackball).c_str(),
                            host.camera().trackball))
            host.execute(Command::ToggleTrackball);
        printCheckMenu(host.view().printCheck());
        if (ImGui::MenuItem("Slices", host.commands().shortcutText(Command::ToggleSlices).c_str(),
                            host.view().slices().shown(), host.whyNot(Command::ToggleSlices).empty()))
            host.execute(Command::ToggleSlices);
        clipPlaneMenu(host);
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
