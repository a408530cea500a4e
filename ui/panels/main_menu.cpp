#include "ui/app/sculpt_app.h"
#include "ui/modes/primitives_mode.h"
#include "ui/panels/panels.h"

#include <imgui.h>

namespace sculpt::ui {

void commandMenuItem(SculptApp& app, int command, bool enabled)
{
    const Command c = Command(command);
    const std::string keys = shortcutText(c);
    if (ImGui::MenuItem(commandInfo(c).label, keys.empty() ? nullptr : keys.c_str(), false, enabled)) app.execute(c);
    commandTooltip(command);
}

void commandTooltip(int command)
{
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    const Command c = Command(command);
    const std::string keys = shortcutText(c);
    ImGui::SetTooltip("%s%s%s", commandInfo(c).help, keys.empty() ? "" : "\nKey: ", keys.c_str());
}

void drawMainMenu(SculptApp& app)
{
    if (!ImGui::BeginMainMenuBar()) return;
    const auto item = [&app](Command c, bool enabled = true) { commandMenuItem(app, int(c), enabled); };
    if (ImGui::BeginMenu("File")) {
        item(Command::New);
        item(Command::Open);
        if (ImGui::BeginMenu("Open Recent", !app.recent().entries().empty())) {
            for (const auto& path : app.recent().entries()) {
                if (ImGui::MenuItem(path.string().c_str())) app.openRecent(path);
            }
            ImGui::EndMenu();
        }
        item(Command::Import, !app.job());
        ImGui::Separator();
        item(Command::Save);
        item(Command::SaveAs);
        item(Command::ExportMesh);
        item(Command::SaveStrokes);
        ImGui::Separator();
        item(Command::LoadTarget, !app.job());
        ImGui::Separator();
        item(Command::Quit);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        item(Command::Undo, !app.job() && app.document().session().history().undoCount() > 0);
        item(Command::Redo, !app.job() && app.document().session().history().redoCount() > 0);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Primitives")) {
        item(Command::AddPrimitive, !app.job());
        item(Command::RemovePrimitive, app.mode<PrimitivesMode>() != nullptr);
        item(Command::BakePrimitives, app.mode<PrimitivesMode>() != nullptr && !app.job());
        ImGui::Separator();
        item(Command::LoadScene, !app.job());
        item(Command::SaveScene, app.mode<PrimitivesMode>() != nullptr);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Filters")) {
        item(Command::SmoothModel, !app.job());
        item(Command::OffsetModel, !app.job());
        ImGui::Separator();
        item(Command::MorphTo, !app.job());
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        for (int s = 0; s < 4; ++s) {
            if (ImGui::MenuItem(kShadingNames[s], nullptr, int(app.look().shading()) == s))
                app.look().setShading(Shading(s));
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Flat Shading", shortcutText(Command::ToggleFlat).c_str(), app.look().flat()))
            app.execute(Command::ToggleFlat);
        if (ImGui::MenuItem("Wireframe", shortcutText(Command::ToggleWireframe).c_str(), app.look().wireframe()))
            app.execute(Command::ToggleWireframe);
        if (ImGui::MenuItem("Scales", shortcutText(Command::ToggleScales).c_str(), app.scalesShown()))
            app.execute(Command::ToggleScales);
        if (ImGui::MenuItem("X-Ray", shortcutText(Command::ToggleXRay).c_str(), app.look().xray()))
            app.execute(Command::ToggleXRay);
        if (ImGui::MenuItem("Target Ghost", shortcutText(Command::ToggleGhost).c_str(), app.ghostShown(),
                            bool(app.brush().target.shape)))
            app.execute(Command::ToggleGhost);
        if (ImGui::MenuItem("Trackball Orbit", shortcutText(Command::ToggleTrackball).c_str(), app.camera().trackball))
            app.execute(Command::ToggleTrackball);
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
