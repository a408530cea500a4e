#include "core/motion/morph_verdict.h"
#include "ui/app/sculpt_app.h"
#include "ui/modes/morph_mode.h"
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
bool answerButton(SculptApp& app, Command command, const char* label = nullptr)
{
    const std::string keys = app.commands().shortcutText(command);
    const std::string text =
        std::string(label ? label : app.commands().row(command).label) + " (" + keys.substr(0, keys.find(", ")) + ")";
    const bool clicked = ImGui::Button(text.c_str());
    if (clicked) app.execute(command);
    return clicked;
}

/// What each prompt's file chooser lists.
FileKinds kindsOf(Dialogs::Prompt prompt)
{
    using P = Dialogs::Prompt;
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
    case P::ExportMesh: return {{".ply", ".obj", ".stl"}};
    case P::SaveStrokes:
    case P::LoadScene:
    case P::SaveScene: return {{".json"}};
    case P::Import: return {join(scans, meshes), true, true};
    case P::Target:
    case P::Morph: return {join(join({".vdb"}, scans), meshes), true, true};
    case P::MorphExport: return {{".vdb"}, false, true};
    default: return {};
    }
}

/// "`okLabel` (Enter)" and "Cancel (Esc)" closing the dialog's window. `entered`: Enter ended the
/// edit of one of its fields (the routed Enter waits for a field being edited: its text is
/// complete only here).
void okOrCancel(SculptApp& app, const char* okLabel, bool entered)
{
    const bool ok = answerButton(app, Command::DialogConfirm, okLabel);
    ImGui::SameLine();
    answerButton(app, Command::DialogCancel, "Cancel");
    ImGui::End();
    if (entered && !ok && app.whyNot(Command::DialogConfirm).empty()) app.execute(Command::DialogConfirm);
}

void errorDialog(SculptApp& app)
{
    beginDialog("Error");
    ImGui::PushTextWrapPos(520.f);
    ImGui::TextUnformatted(app.dialogs().error.c_str());
    ImGui::PopTextWrapPos();
    answerButton(app, Command::DialogConfirm);
    ImGui::End();
}

void recoveryDialog(SculptApp& app)
{
    beginDialog("Recover unsaved work?");
    ImGui::Text("Sculpt did not close cleanly. An autosave newer than the document exists:");
    ImGui::TextDisabled("%s", app.dialogs().recovery->string().c_str());
    if (!answerButton(app, Command::AnswerRecover)) {
        ImGui::SameLine();
        answerButton(app, Command::AnswerDiscard);
    }
    ImGui::End();
}

void gridDialog(SculptApp& app)
{
    const Dialogs::GridChoice choice = *app.dialogs().gridChoice;  // a copy: a button closes the dialog
    beginDialog("Which level set?");
    ImGui::Text("%s holds several level sets and none is named 'surface'.", choice.file.filename().string().c_str());
    ImGui::Text("Choose the one to sculpt; the others are kept in the file when it is saved.");
    for (std::size_t i = 0; i < choice.grids.size() && app.dialogs().gridChoice; ++i) {
        if (i < 9) answerButton(app, Command(int(Command::ChooseGrid1) + int(i)), choice.grids[i].c_str());
        else if (ImGui::Button(choice.grids[i].c_str())) app.openChosenGrid(choice.grids[i]);
    }
    answerButton(app, Command::DialogCancel, "Cancel");
    ImGui::End();
}

void unsavedDialog(SculptApp& app)
{
    beginDialog("Unsaved changes");
    ImGui::Text("%s has unsaved changes. Save them first?", app.document().title().c_str());
    if (answerButton(app, Command::AnswerSave)) return ImGui::End();
    ImGui::SameLine();
    if (answerButton(app, Command::AnswerDiscard)) return ImGui::End();
    ImGui::SameLine();
    answerButton(app, Command::DialogCancel, "Cancel");
    ImGui::End();
}

void newDialog(SculptApp& app)
{
    Dialogs& d = app.dialogs();
    beginDialog("New document");
    int kind = int(d.newShape.kind);
    if (ImGui::Combo("shape", &kind, kShapeNames, int(std::size(kShapeNames)))) d.newShape.kind = NewShape::Kind(kind);
    ImGui::InputDouble("size", &d.newShape.size, 1.0, 10.0, "%.3g");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Sphere radius, box half side or torus major radius (world units)");
    ImGui::InputDouble("voxel size", &d.newShape.voxelSize, 0.05, 0.5, "%.3g");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Smaller is finer and costs more memory");
    okOrCancel(app, "Create", pressed(GLFW_KEY_ENTER));
}

void pathDialog(SculptApp& app, const char* title, const char* hint)
{
    Dialogs& d = app.dialogs();
    beginDialog(title);
    ImGui::TextDisabled("%s", hint);
    okOrCancel(app, "OK", fileField(app, kindsOf(d.prompt), "##path"));
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

void filterDialog(SculptApp& app)
{
    Dialogs& d = app.dialogs();
    ModelFilter& f = d.filter;
    static const char* kTitles[] = {"Smooth Model", "Offset Model", "Hollow", "Remove Small Islands"};
    beginDialog(kTitles[int(f.kind)]);
    if (d.focusField) ImGui::SetKeyboardFocusHere();
    d.focusField = false;
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
    okOrCancel(app, "Run", pressed(GLFW_KEY_ENTER));
}

void morphDialog(SculptApp& app)
{
    Dialogs& d = app.dialogs();
    MorphOptions& m = d.morph;
    beginDialog("Morph To");
    ImGui::TextDisabled(
        "The target: a .vdb document, a scan or a mesh (path, then Enter; Tab completes; the loaded target if any)");
    const bool entered = fileField(app, kindsOf(d.prompt), "##target");
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
    okOrCancel(app, "Run", entered);
}

}  // namespace

/// The tracked mesh's line: the shown frame's quality, and the wireframe's switch.
void trackedMeshLine(MorphMode& mode)
{
    const MorphTracking& tracking = *mode.frames().run().tracking;
    const TrackedFrame& f = tracking.frames().at(std::size_t(mode.frames().shown()));
    bool shown = mode.wire().shown();
    if (ImGui::Checkbox("tracked mesh", &shown)) mode.wire().setShown(shown);
    ImGui::SameLine();
    const double e = tracking.edgeLength();
    // A segment holds every vertex its frames have had (tracked_sequence.h); the quality is this frame's.
    const std::vector<TrackedSegment>& segments = tracking.sequence().segments();
    ImGui::TextDisabled("segment %zu of %zu, %zu vertices; this frame %zu, smallest angle %.1f deg, edges %.2f-%.2f e, "
                        "%zu flagged",
                        f.segment + 1, segments.size(), segments.at(f.segment).ids.size(), f.quality.vertices,
                        f.quality.smallestAngle, f.quality.shortestEdge / e, f.quality.longestEdge / e, f.flagged);
}

void drawMorphPanel(SculptApp& app, MorphMode& mode)
{
    MorphFrames& frames = mode.frames();
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y - 48.f), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::Begin("Morph", nullptr, kDialogFlags);
    int shown = frames.shown();
    ImGui::SetNextItemWidth(360.f);
    if (ImGui::SliderInt("frame", &shown, 0, frames.count() - 1)) frames.show(shown);
    const auto button = [&app](const char* label, Command command) {
        if (ImGui::Button(label)) app.execute(command);
        commandTooltip(app, command);
        ImGui::SameLine();
    };
    button("<", Command::StepUp);
    button(frames.playing() ? "Pause" : "Play", Command::MorphPlay);
    button(">", Command::StepDown);
    button("Keep frame", Command::MorphKeep);
    button("Export frames...", Command::MorphExport);
    if (ImGui::Button("Close (Esc)")) app.execute(Command::Cancel);
    if (frames.run().tracking) trackedMeshLine(mode);
    const MorphSummary& s = frames.run().summary;
    const std::string verdict = morphVerdict(s, frames.shownField().voxelSize());
    ImGui::PushTextWrapPos(560.f);
    ImGui::TextDisabled("%d steps, final distance %.3g: %s", s.steps, s.finalDistanceWorld, verdict.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

void drawJobPanel(SculptApp& app)
{
    const BackgroundJob* job = app.job();
    if (!job) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y - 48.f), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::Begin("Job", nullptr, kDialogFlags | ImGuiWindowFlags_NoTitleBar);
    ImGui::Text("%s%s", job->label().c_str(), job->cancelRequested() ? ": cancelling..." : "");
    ImGui::ProgressBar(float(job->progress()), ImVec2(320.f, 0.f));
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)")) app.execute(Command::Cancel);
    ImGui::End();
}

void drawDialogs(SculptApp& app)
{
    Dialogs& d = app.dialogs();
    if (!d.error.empty()) return errorDialog(app);
    if (d.recovery) return recoveryDialog(app);
    if (d.gridChoice) return gridDialog(app);
    if (d.afterUnsaved) return unsavedDialog(app);
    switch (d.prompt) {
    case Dialogs::Prompt::New: return newDialog(app);
    case Dialogs::Prompt::Open: return pathDialog(app, "Open", "A .vdb document (path, then Enter; Tab completes)");
    case Dialogs::Prompt::SaveAs: return pathDialog(app, "Save As", "A .vdb file to write");
    case Dialogs::Prompt::ExportMesh: return pathDialog(app, "Export Mesh", "A .ply, .obj or .stl file to write");
    case Dialogs::Prompt::SaveStrokes:
        return pathDialog(app, "Save Strokes", "A .json stroke script for `sculpt apply`");
    case Dialogs::Prompt::SmoothModel:
    case Dialogs::Prompt::OffsetModel:
    case Dialogs::Prompt::HollowModel:
    case Dialogs::Prompt::RemoveIslands: return filterDialog(app);
    case Dialogs::Prompt::Morph: return morphDialog(app);
    case Dialogs::Prompt::MorphExport: return pathDialog(app, "Export Frames", "A directory for frame_0000.vdb ...");
    case Dialogs::Prompt::LoadScene:
        return pathDialog(app, "Load Scene", "A primitive scene (.json) to place and bake");
    case Dialogs::Prompt::SaveScene: return pathDialog(app, "Save Scene", "A .json scene file for `sculpt build`");
    case Dialogs::Prompt::Import:
        return pathDialog(
            app, "Import",
            "A scan (.nii, .nii.gz, .nrrd, .mha, a DICOM directory or file) or a mesh (.obj, .ply, .stl, .off)");
    case Dialogs::Prompt::Target:
        return pathDialog(app, "Load Target",
                          "A document, scan or mesh for the follow brush (O) and the morph, shown as a ghost (H)");
    case Dialogs::Prompt::None: return;
    }
}

}  // namespace sculpt::ui
