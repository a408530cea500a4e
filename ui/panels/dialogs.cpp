// SPDX-License-Identifier: Apache-2.0
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace sculpt::ui {

namespace {

constexpr ImGuiWindowFlags kDialogFlags =
    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;

bool beginDialog(const char* title)
{
    const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.4f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowFocus();
    return ImGui::Begin(title, nullptr, kDialogFlags);
}

bool pressed(int key) { return ImGui::IsKeyPressed(key, false); }

/// A button for a dialog's answer, "Save (S)": its key reaches the command through the table.
bool answerButton(PanelHost& host, Command command, const char* label = nullptr)
{
    const std::string keys = host.commands().shortcutText(command);
    const std::string text =
        std::string(label ? label : host.commands().row(command).label) + " (" + keys.substr(0, keys.find(", ")) + ")";
    const bool clicked = ImGui::Button(text.c_str());
    if (clicked) host.execute(command);
    return clicked;
}

/// What each prompt's file chooser lists.
FileKinds kindsOf(Prompt::Kind prompt)
{
    using P = Prompt::Kind;
    const std::vector<std::string> scans = {".nii", ".nii.gz", ".nrrd",   ".nhdr", ".mha",
                                            ".mhd", ".inr",    ".inr.gz", ".dcm"};
    const std::vector<std::string> meshes = {".obj", ".ply", ".stl", ".off"};
    const auto join = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    switch (prompt) {
    case P::Open:
    case P::SaveAs: return {{".vdb"}};
    case P::ExportMesh: return {{".ply", ".obj", ".stl", ".3mf"}};
    case P::ExportLabels: return {{".nii", ".nii.gz", ".nrrd", ".seg.nrrd"}};
    case P::SaveStrokes:
    case P::LoadScene:
    case P::SaveScene: return {{".json"}};
    case P::Import: return {join(join({".vdb"}, scans), meshes), true, true};  // .vdb: a document's kept scan
    case P::Target:
    case P::Morph: return {join(join({".vdb"}, scans), meshes), true, true};
    case P::MorphExport: return {{".vdb"}, false, true};
    default: return {};
    }
}

/// "`okLabel` (Enter)" and "Cancel (Esc)" closing the dialog's window. `entered`: Enter ended the
/// edit of one of its fields (the routed Enter waits for a field being edited: its text is
/// complete only here).
void okOrCancel(PanelHost& host, const char* okLabel, bool entered)
{
    const bool ok = answerButton(host, Command::DialogConfirm, okLabel);
    ImGui::SameLine();
    answerButton(host, Command::DialogCancel, "Cancel");
    ImGui::End();
    if (entered && !ok && host.whyNot(Command::DialogConfirm).empty()) host.execute(Command::DialogConfirm);
}

void errorDialog(PanelHost& host)
{
    beginDialog("Error");
    ImGui::PushTextWrapPos(520.f);
    ImGui::TextUnformatted(host.notices().error().c_str());
    ImGui::PopTextWrapPos();
    answerButton(host, Command::DialogConfirm);
    ImGui::End();
}

void recoveryDialog(PanelHost& host)
{
    beginDialog("Recover unsaved work?");
    ImGui::Text("Sculpt did not close cleanly. An autosave newer than the document exists:");
    ImGui::TextDisabled("%s", host.files().offeringRecovery()->string().c_str());
    if (!answerButton(host, Command::AnswerRecover)) {
        ImGui::SameLine();
        answerButton(host, Command::AnswerDiscard);
    }
    ImGui::End();
}

void gridDialog(PanelHost& host)
{
    const DocumentFiles::GridChoice choice = *host.files().askingGrid();  // a copy: a button closes the dialog
    beginDialog("Which level set?");
    ImGui::Text("%s holds several level sets and none is named 'surface'.", choice.file.filename().string().c_str());
    ImGui::Text("Choose the one to sculpt; the others are kept in the file when it is saved.");
    for (std::size_t i = 0; i < choice.grids.size() && host.files().askingGrid(); ++i) {
        if (i < 9) answerButton(host, Command(int(Command::ChooseGrid1) + int(i)), choice.grids[i].c_str());
        else if (ImGui::Button(choice.grids[i].c_str())) host.files().chooseGrid(choice.grids[i]);
    }
    answerButton(host, Command::DialogCancel, "Cancel");
    ImGui::End();
}

void unsavedDialog(PanelHost& host)
{
    beginDialog("Unsaved changes");
    ImGui::Text("%s has unsaved changes. Save them first?", host.document().title().c_str());
    if (answerButton(host, Command::AnswerSave)) return ImGui::End();
    ImGui::SameLine();
    if (answerButton(host, Command::AnswerDiscard)) return ImGui::End();
    ImGui::SameLine();
    answerButton(host, Command::DialogCancel, "Cancel");
    ImGui::End();
}

void newDialog(PanelHost& host)
{
    Dialogs& d = host.dialogs();
    beginDialog("New document");
    int kind = int(d.newShape.kind);
    if (ImGui::Combo("shape", &kind, kShapeNames, int(std::size(kShapeNames)))) d.newShape.kind = NewShape::Kind(kind);
    ImGui::InputDouble("size", &d.newShape.size, 1.0, 10.0, "%.3g");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Sphere radius, box half side or torus major radius (world units)");
    ImGui::InputDouble("voxel size", &d.newShape.voxelSize, 0.05, 0.5, "%.3g");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Smaller is finer and costs more memory");
    okOrCancel(host, "Create", pressed(GLFW_KEY_ENTER));
}

void pathDialog(PanelHost& host, const char* title, const char* hint)
{
    Dialogs& d = host.dialogs();
    beginDialog(title);
    ImGui::TextDisabled("%s", hint);
    okOrCancel(host, "OK", fileField(host, kindsOf(d.prompt.kind), "##path"));
}

void hollowFields(ModelFilter& f)
{
    ImGui::InputDouble("wall thickness", &f.hollow.thicknessWorld, 0.1, 1.0, "%.4g");
    f.hollow.thicknessWorld = std::max(f.hollow.thicknessWorld, 1e-3);
    static const char* kSides[] = {"inside", "medial", "outside"};
    int side = int(f.hollow.side);
    ImGui::Combo("wall", &side, kSides, 3);
    f.hollow.side = ShellSide(side);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Inside the surface (it stays where it is), centred on it, or around it");
    ImGui::InputDouble("closing", &f.hollow.closingWorld, 0.1, 1.0, "%.4g");
    f.hollow.closingWorld = std::max(f.hollow.closingWorld, 0.0);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Smooths the cavity: no part of it narrower than twice this");
    ImGui::Checkbox("drain holes", &f.drain);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A hole through the bottom wall under each cavity's lowest point");
    ImGui::InputDouble("hole radius", &f.drainRadiusWorld, 0.1, 1.0, "%.4g");
    f.drainRadiusWorld = std::max(f.drainRadiusWorld, 1e-3);
    static const char* kAxes[] = {"x up", "y up", "z up"};
    int axis = f.up.x() != 0.0 ? 0 : f.up.y() != 0.0 ? 1 : 2;
    ImGui::Combo("print direction", &axis, kAxes, 3);
    f.up = openvdb::Vec3d(axis == 0, axis == 1, axis == 2);
}

void filterDialog(PanelHost& host)
{
    Dialogs& d = host.dialogs();
    ModelFilter& f = d.filter;
    static const char* kTitles[] = {"Smooth Model", "Offset Model", "Hollow", "Remove Small Islands"};
    beginDialog(kTitles[int(f.kind)]);
    if (d.prompt.focusField) ImGui::SetKeyboardFocusHere();
    d.prompt.focusField = false;
    switch (f.kind) {
    case ModelFilter::Kind::Smooth:
        ImGui::InputInt("iterations", &f.iterations, 1, 10);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Stable steps of mean-curvature flow: more is smoother");
        ImGui::Checkbox("keep volume", &f.keepVolume);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Hold the enclosed volume (otherwise smoothing shrinks the model)");
        break;
    case ModelFilter::Kind::Offset:
        ImGui::InputDouble("distance", &f.distanceWorld, 0.1, 1.0, "%.4g");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("World units along the normal: > 0 grows, < 0 shrinks");
        break;
    case ModelFilter::Kind::Hollow: hollowFields(f); break;
    case ModelFilter::Kind::RemoveIslands:
        ImGui::InputDouble("smaller than", &f.minIslandVolume, 0.1, 1.0, "%.4g");
        f.minIslandVolume = std::max(f.minIslandVolume, 0.0);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Volume (world units cubed): the islands under it are removed");
        break;
    }
    ImGui::TextDisabled("Runs as a job: the view stays live, Esc cancels, Ctrl+Z undoes it");
    okOrCancel(host, "Run", pressed(GLFW_KEY_ENTER));
}

void morphDialog(PanelHost& host)
{
    Dialogs& d = host.dialogs();
    MorphOptions& m = d.morph;
    beginDialog("Morph To");
    ImGui::TextDisabled(
        "The target: a .vdb document, a scan or a mesh (path, then Enter; Tab completes; the loaded target if any)");
    const bool entered = fileField(host, kindsOf(d.prompt.kind), "##target");
    ImGui::InputInt("frames", &m.frames, 1, 5);
    m.frames = std::clamp(m.frames, 2, 1000);
    ImGui::InputInt("max steps", &m.maxSteps, 100, 1000);
    m.maxSteps = std::clamp(m.maxSteps, 1, 1000000);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Steps of the motion at most (a stalled morph stops earlier)");
    ImGui::Checkbox("keep volume", &m.keepVolume);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Frame volumes on the straight line between the two shapes'");
    ImGui::Checkbox("align", &m.align);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("First move the model's centroid onto the target's");
    // Ctrl+T: the path field keeps the keyboard while the dialog is open.
    if (ImGui::GetIO().KeyCtrl && pressed(GLFW_KEY_T)) d.morphTracked = !d.morphTracked;
    ImGui::Checkbox("tracked mesh (Ctrl+T)", &d.morphTracked);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Also follow the surface with a mesh that keeps its vertices and triangles while it can\n"
                          "(for point caches, shape keys and USD: exported with the frames)");
    float tolerance = float(m.toleranceVoxels);
    ImGui::SetNextItemWidth(120.f);
    if (ImGui::InputFloat("tolerance (voxels)", &tolerance, 0.f, 0.f, "%.2f") && tolerance > 0.f)
        m.toleranceVoxels = tolerance;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Converged once the surface is this close to the target's everywhere it resolves it");
    okOrCancel(host, "Run", entered);
}

}  // namespace

void beginBottomPanel(const char* title, bool titleBar)
{
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y - 48.f), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::Begin(title, nullptr, kDialogFlags | (titleBar ? 0 : ImGuiWindowFlags_NoTitleBar));
}

void drawJobPanel(PanelHost& host)
{
    const BackgroundJob* job = host.workspace().jobs().job();
    if (!job) return;
    beginBottomPanel("Job", false);
    ImGui::Text("%s%s", job->label().c_str(), job->cancelRequested() ? ": cancelling..." : "");
    ImGui::ProgressBar(float(job->progress()), ImVec2(320.f, 0.f));
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)")) host.execute(Command::Cancel);
    ImGui::End();
}

void drawDialogs(PanelHost& host)
{
    const DocumentFiles& files = host.files();
    if (!host.notices().error().empty()) return errorDialog(host);
    if (files.offeringRecovery()) return recoveryDialog(host);
    if (files.askingGrid()) return gridDialog(host);
    if (files.askingUnsaved()) return unsavedDialog(host);
    switch (host.dialogs().prompt.kind) {
    case Prompt::Kind::New: return newDialog(host);
    case Prompt::Kind::Open: return pathDialog(host, "Open", "A .vdb document (path, then Enter; Tab completes)");
    case Prompt::Kind::SaveAs: return pathDialog(host, "Save As", "A .vdb file to write");
    case Prompt::Kind::ExportMesh: return pathDialog(host, "Export Mesh", "A .ply, .obj, .stl or .3mf file to write");
    case Prompt::Kind::ExportLabels:
        return pathDialog(host, "Export Segmentation",
                          "A .nii, .nii.gz, .nrrd or .seg.nrrd (3D Slicer) label map to write on the kept scan's "
                          "lattice: a label per piece");
    case Prompt::Kind::SaveStrokes: return pathDialog(host, "Save Strokes", "A .json stroke script for `sculpt apply`");
    case Prompt::Kind::SmoothModel:
    case Prompt::Kind::OffsetModel:
    case Prompt::Kind::HollowModel:
    case Prompt::Kind::RemoveIslands: return filterDialog(host);
    case Prompt::Kind::Morph: return morphDialog(host);
    case Prompt::Kind::MorphExport: return pathDialog(host, "Export Frames", "A directory for frame_0000.vdb ...");
    case Prompt::Kind::LoadScene: return pathDialog(host, "Load Scene", "A primitive scene (.json) to place and bake");
    case Prompt::Kind::SaveScene: return pathDialog(host, "Save Scene", "A .json scene file for `sculpt build`");
    case Prompt::Kind::Import:
        return pathDialog(
            host, "Import",
            "A scan (.nii, .nii.gz, .nrrd, .mha, a DICOM directory or file) or a mesh (.obj, .ply, .stl, .off)");
    case Prompt::Kind::Target:
        return pathDialog(host, "Load Target",
                          "A document, scan or mesh for the follow brush (O) and the morph, shown as a ghost (H)");
    case Prompt::Kind::None: return;
    }
}

}  // namespace sculpt::ui
