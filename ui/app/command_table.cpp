// The window's own commands (files, edits of the whole model, the view, modes, dialogs), each
// added once to its registry: label, help, keys, when it can run and what it does. The tools add
// theirs (ui/tools). Navigation follows Blender's sculpt mode where it has a key.

#include "ui/app/sculpt_app.h"
#include "ui/input/input_event.h"
#include "ui/modes/import_mode.h"
#include "ui/modes/morph_mode.h"
#include "ui/modes/primitives_mode.h"
#include "ui/window/window.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace sculpt::ui {

namespace {

constexpr int kCtrlShift = kControl | kShift;

void toggle(bool& flag) { flag = !flag; }

/// A row as this file writes it: its rule and action take the app (they reach its insides, being
/// written in its member addCommands).
struct AppRow {
    Command command;
    const char* label;
    const char* help;
    std::vector<Chord> chords;
    std::string (*blocked)(const SculptApp& app);
    void (*run)(SculptApp& app);
    Scope scope = Scope::View;
};

// Rows that differ only in their data: a mask operation, a view to look along, an orbit step.
template <MaskOperation operation>
AppRow maskRow(Command command, const char* label, const char* help, std::vector<Chord> chords,
               std::string (*blocked)(const SculptApp&))
{
    return {command, label, help, std::move(chords), blocked, [](SculptApp& a) { a.editMask(operation); }};
}

template <AxisView view>
AppRow viewRow(Command command, const char* label, const char* help, std::vector<Chord> chords)
{
    return {command, label, help, std::move(chords), nullptr, [](SculptApp& a) { a.camera().axisView(view); }};
}

template <int yawDegrees, int pitchDegrees>
AppRow orbitRow(Command command, const char* label, const char* help, std::vector<Chord> chords)
{
    void (*orbit)(SculptApp&) = [](SculptApp& a) { a.camera().orbitDegrees(yawDegrees, pitchDegrees); };
    return {command, label, help, std::move(chords), nullptr, orbit};
}

/// "Which level set?": the one numbered `number` (its key).
template <int number>
AppRow gridRow()
{
    constexpr std::size_t index = number - 1;
    return {Command(int(Command::ChooseGrid1) + int(index)),
            "Level set",
            "Which level set?: open the one with this number",
            {{GLFW_KEY_1 + int(index)}},
            [](const SculptApp& a) {
                const auto& choice = a.dialogs().gridChoice;
                if (choice && index < choice->grids.size()) return std::string();
                return std::string("no level set has the number ") + std::to_string(number);
            },
            [](SculptApp& a) { a.openChosenGrid(a.dialogs().gridChoice->grids[index]); },
            Scope::Dialog};
}

}  // namespace

void SculptApp::addCommands()
{
    using App = SculptApp;
    using P = Dialogs::Prompt;
    // When a command may not run: these rules grey out its menu item too.
    static constexpr auto idle = +[](const App& a) { return a.waitReason(); };
    static constexpr auto primitivesOrIdle =
        +[](const App& a) { return a.mode<PrimitivesMode>() ? std::string() : a.waitReason(); };
    static constexpr auto placing = +[](const App& a) {
        return a.mode<PrimitivesMode>() ? std::string()
                                        : std::string("no primitives are being placed: Shift+A adds one");
    };
    static constexpr auto importing = +[](const App& a) {
        return a.mode<ImportMode>() ? std::string()
                                    : std::string("no import is open: File > Import (Ctrl+I) opens one");
    };
    static constexpr auto morphing = +[](const App& a) {
        return a.mode<MorphMode>() ? std::string()
                                   : std::string("no morph frames on show: Filters > Morph To makes them");
    };
    static constexpr auto accepting = +[](const App& a) {
        if (a.mJobs.running()) return a.waitReason();
        return a.mMode ? std::string()
                       : std::string("nothing to apply: Enter applies an import, primitives or a frame");
    };
    static constexpr auto unsavedOpen = +[](const App& a) {
        return a.mDialogs.afterUnsaved ? std::string() : std::string("no unsaved changes are being asked about");
    };
    static constexpr auto recoveryOpen =
        +[](const App& a) { return a.mDialogs.recovery ? std::string() : std::string("no autosave is being offered"); };
    static constexpr auto openFilter = +[](App& a, ModelFilter::Kind kind, P prompt) {
        a.mDialogs.filter.kind = kind;
        a.openPrompt(prompt, a.mDialogs.path);
    };
    static constexpr auto step = +[](App& a, int direction) {
        if (a.mMode) a.mMode->step(direction);
    };
    const std::vector<AppRow> rows = {
        {Command::RadiusDrag,
         "Radius",
         "Then move the mouse to size the brush; click or Enter to keep, Esc to undo",
         {{GLFW_KEY_F}},
         nullptr,
         [](App& a) { a.mDrag = Drag::Radius, a.mDragStartX = a.mPointer.x(), a.mDragStartValue = a.mBrush.radius; }},
        {Command::StrengthDrag,
         "Strength",
         "Then move the mouse to set the strength",
         {{GLFW_KEY_F, kShift}},
         nullptr,
         [](App& a) {
             a.mDrag = Drag::Strength, a.mDragStartX = a.mPointer.x(), a.mDragStartValue = a.mBrush.strength;
         }},
        {Command::Undo,
         "Undo",
         "Undo the last stroke",
         {{GLFW_KEY_Z, kControl}},
         [](const App& a) {
             if (!a.waitReason().empty()) return a.waitReason();
             return a.mDocument->undoLabels().empty() ? std::string("nothing to undo") : std::string();
         },
         [](App& a) { a.mDocument->undo(); }},
        {Command::Redo,
         "Redo",
         "Redo the stroke undone last",
         {{GLFW_KEY_Z, kCtrlShift}, {GLFW_KEY_Y, kControl}},
         [](const App& a) {
             if (!a.waitReason().empty()) return a.waitReason();
             return a.mDocument->redoLabels().empty() ? std::string("nothing to redo") : std::string();
         },
         [](App& a) { a.mDocument->redo(); }},
        {Command::New,
         "New...",
         "A new document from a sphere, box or torus",
         {{GLFW_KEY_N, kControl}},
         idle,
         [](App& a) {
             if (a.guardUnsaved(Command::New)) a.openPrompt(P::New);
         }},
        {Command::Open,
         "Open...",
         "Open a .vdb document",
         {{GLFW_KEY_O, kControl}},
         idle,
         [](App& a) {
             if (a.guardUnsaved(Command::Open)) a.openPrompt(P::Open);
         }},
        {Command::Save,
         "Save",
         "Save the document",
         {{GLFW_KEY_S, kControl}},
         nullptr,
         [](App& a) {
             if (a.mDocument->path().empty()) a.execute(Command::SaveAs);
             else a.saveTo(a.mDocument->path());
         }},
        {Command::SaveAs,
         "Save As...",
         "Save the document under a new name",
         {{GLFW_KEY_S, kCtrlShift}},
         nullptr,
         [](App& a) { a.openPrompt(P::SaveAs, a.mDocument->path().string()); }},
        {Command::ExportMesh,
         "Export Mesh...",
         "Write the surface as PLY, OBJ or STL",
         {{GLFW_KEY_E, kControl}},
         nullptr,
         [](App& a) { a.openPrompt(P::ExportMesh, a.besideDocument(".ply", "sculpt.ply")); }},
        {Command::SaveStrokes,
         "Save Strokes...",
         "Write this session's strokes for `sculpt apply`",
         {},
         nullptr,
         [](App& a) { a.openPrompt(P::SaveStrokes, a.besideDocument(".strokes.json", "strokes.json")); }},
        {Command::Import,
         "Import...",
         "A scan (NIfTI, NRRD, MetaImage, DICOM) or a mesh: preview the surface, then a new document, or "
         "union/difference with this one",
         {{GLFW_KEY_I, kControl}},
         idle,
         [](App& a) { a.openPrompt(P::Import); }},
        {Command::ApplyImport,
         "Apply Import",
         "Import with the panel's settings (a job)",
         {},
         importing,
         [](App& a) { a.acceptMode(); }},
        {Command::AddPrimitive,
         "Add Primitive",
         "Opens the Primitives panel and adds a blob where the pointer is on the surface (click or drag to place it)",
         {{GLFW_KEY_A, kShift}},
         primitivesOrIdle,
         [](App& a) { a.addPrimitive(SkeletonType::Point); }},
        {Command::RemovePrimitive,
         "Remove Primitive",
         "Removes the selected primitive (Primitives panel)",
         {{GLFW_KEY_DELETE}},
         placing,
         [](App& a) { a.mode<PrimitivesMode>()->draft().removeSelected(); }},
        {Command::BakePrimitives,
         "Bake Primitives",
         "Combines the panel's primitives into the model by the scene's operation (one undo step)",
         {},
         [](const App& a) { return a.mJobs.running() ? a.waitReason() : placing(a); },
         [](App& a) { a.acceptMode(); }},
        {Command::LoadScene,
         "Load Scene...",
         "Opens a primitive scene file in the Primitives panel",
         {{GLFW_KEY_O, kControl | kAlt}},
         primitivesOrIdle,
         [](App& a) { a.openPrompt(P::LoadScene); }},
        {Command::SaveScene,
         "Save Scene...",
         "Writes the panel's primitives as a scene file for `sculpt build`",
         {{GLFW_KEY_S, kControl | kAlt}},
         placing,
         [](App& a) { a.openPrompt(P::SaveScene, "scene.json"); }},
        {Command::LoadTarget,
         "Load Target...",
         "A document, scan or mesh for the follow brush and the morph, shown as a ghost (a job)",
         {{GLFW_KEY_T, kControl}},
         idle,
         [](App& a) { a.openPrompt(P::Target, a.mBrush.target.path.string()); }},
        {Command::Quit,
         "Quit",
         "Close Sculpt (asks first if there are unsaved changes)",
         {{GLFW_KEY_Q, kControl}},
         nullptr,
         [](App& a) {
             if (a.guardUnsaved(Command::Quit)) a.mQuit = true;  // a running job is cancelled on the way out
         }},
        {Command::SmoothModel,
         "Smooth Model...",
         "Mean-curvature flow over the whole model, as a job (Esc cancels; one undo step)",
         {{GLFW_KEY_S, kAlt}},
         idle,
         [](App& a) { openFilter(a, ModelFilter::Kind::Smooth, P::SmoothModel); }},
        {Command::OffsetModel,
         "Offset Model...",
         "Grow or shrink the whole model along its normal, as a job (Esc cancels; one undo step)",
         {{GLFW_KEY_O, kAlt}},
         idle,
         [](App& a) { openFilter(a, ModelFilter::Kind::Offset, P::OffsetModel); }},
        {Command::HollowModel,
         "Hollow...",
         "Make the model a shell of a wall thickness with drain holes (for resin prints), as a job",
         {},
         idle,
         [](App& a) { openFilter(a, ModelFilter::Kind::Hollow, P::HollowModel); }},
        {Command::RemoveIslands,
         "Remove Small Islands...",
         "Remove the disjoint bits of clay (a scan's specks) under a volume, as a job",
         {},
         idle,
         [](App& a) { openFilter(a, ModelFilter::Kind::RemoveIslands, P::RemoveIslands); }},
        {Command::KeepIsland,
         "Keep Island",
         "Keeps only the island (disjoint bit of clay) under the pointer, as a job",
         {{GLFW_KEY_L, kShift}},
         idle,
         [](App& a) { a.editIslandUnderPointer(true); }},
        {Command::DeleteIsland,
         "Delete Island",
         "Deletes the island (disjoint bit of clay) under the pointer, as a job",
         {{GLFW_KEY_L, kAlt}},
         idle,
         [](App& a) { a.editIslandUnderPointer(false); }},
        {Command::DrillDrainHole,
         "Drill Drain Hole",
         "Drills a drain hole at the pointer, straight in through the wall to the hollow behind it (radius: "
         "Filters > Hollow's hole radius)",
         {{GLFW_KEY_H, kControl}},
         idle,
         [](App& a) { a.drillDrainHoleUnderPointer(); }},
        maskRow<MaskOperation::Invert>(Command::InvertMask, "Invert Mask", "Masked clay becomes free, free clay masked",
                                       {{GLFW_KEY_I, kCtrlShift}}, idle),
        maskRow<MaskOperation::Clear>(Command::ClearMask, "Clear Mask", "Frees the whole model",
                                      {{GLFW_KEY_M, kCtrlShift}}, idle),
        maskRow<MaskOperation::Blur>(Command::BlurMask, "Blur Mask", "Softens the mask's edge by a voxel", {}, idle),
        maskRow<MaskOperation::Sharpen>(Command::SharpenMask, "Sharpen Mask", "Crisps the mask's edge", {}, idle),
        maskRow<MaskOperation::Grow>(Command::GrowMask, "Grow Mask", "Spreads the mask by a voxel", {}, idle),
        maskRow<MaskOperation::Shrink>(Command::ShrinkMask, "Shrink Mask", "Draws the mask back by a voxel", {}, idle),
        {Command::MaskIsland,
         "Mask Island",
         "Masks the island (disjoint bit of clay) under the pointer, as a job",
         {{GLFW_KEY_L, kControl}},
         idle,
         [](App& a) {
             const std::optional<SurfaceHit> hit = a.pickAt(a.mPointer.x(), a.mPointer.y());
             if (!hit) return a.notify("point at the island to mask first");
             MaskSelection selection;
             selection.kind = MaskSelectionKind::Island;
             selection.point = openvdb::Vec3d(hit->position.x, hit->position.y, hit->position.z);
             a.startEdit(maskSelectionEdit(selection, "mask island"));
         }},
        {Command::MaskCavities,
         "Mask Cavities",
         "Masks the creases and hollows, where the surface curves inwards (fully within the crease radius), "
         "as a job",
         {},
         idle,
         [](App& a) {
             MaskSelection selection;
             selection.kind = MaskSelectionKind::Cavity;
             const double voxel = a.mDocument->session().field().voxelSize();
             selection.creaseRadiusWorld = a.mCreaseRadius > 0.0 ? a.mCreaseRadius : 4.0 * voxel;
             a.startEdit(maskSelectionEdit(selection, "mask cavities"));
         }},
        {Command::MaskThinWalls,
         "Mask Thin Walls",
         "Masks the walls thinner than the thickness set here (View > Print Check shows them red), as a job",
         {},
         idle,
         [](App& a) {
             MaskSelection selection;
             selection.kind = MaskSelectionKind::Thin;
             selection.thicknessWorld = a.printCheck().thinnerThan;
             a.startEdit(maskSelectionEdit(selection, "mask thin walls"));
         }},
        {Command::MorphTo,
         "Morph To...",
         "Morph the model into a target document, scan or mesh, as a job; then play and keep frames",
         {{GLFW_KEY_M, kAlt}},
         idle,
         [](App& a) { a.openPrompt(P::Morph, a.mBrush.target.path.string()); }},
        {Command::MorphPlay,
         "Play/Pause Morph",
         "Play the morph's frames (Morph panel)",
         {{GLFW_KEY_SPACE}},
         morphing,
         [](App& a) { a.mode<MorphMode>()->frames().togglePlay(a.mWindow.time()); }},
        {Command::StepUp,
         "Step Up",
         "Morph: the previous frame; Import: the iso-value up by 1% of the range",
         {{GLFW_KEY_PAGE_UP}},
         nullptr,
         [](App& a) { step(a, 1); }},
        {Command::StepDown,
         "Step Down",
         "Morph: the next frame; Import: the iso-value down by 1% of the range",
         {{GLFW_KEY_PAGE_DOWN}},
         nullptr,
         [](App& a) { step(a, -1); }},
        {Command::MorphKeep,
         "Keep Frame",
         "Make the frame shown the document (one undo step)",
         {{GLFW_KEY_K}},
         morphing,
         [](App& a) { a.acceptMode(); }},
        {Command::MorphExport,
         "Export Frames...",
         "Write the morph's frames as DIR/frame_0000.vdb ...",
         {{GLFW_KEY_E, kShift}},
         morphing,
         [](App& a) { a.openPrompt(P::MorphExport, "morph"); }},
        {Command::FrameModel,
         "Frame Model",
         "Fit the model in the view",
         {{GLFW_KEY_HOME}, {GLFW_KEY_KP_DECIMAL}},
         nullptr,
         [](App& a) { a.mView.frameAll(*a.mDocument); }},
        viewRow<AxisView::Front>(Command::ViewFront, "Front", "Look along -z", {{GLFW_KEY_KP_1}, {GLFW_KEY_1}}),
        viewRow<AxisView::Back>(Command::ViewBack, "Back", "Look along +z",
                                {{GLFW_KEY_KP_1, kControl}, {GLFW_KEY_1, kControl}}),
        viewRow<AxisView::Right>(Command::ViewRight, "Right", "Look along -x", {{GLFW_KEY_KP_3}, {GLFW_KEY_3}}),
        viewRow<AxisView::Left>(Command::ViewLeft, "Left", "Look along +x",
                                {{GLFW_KEY_KP_3, kControl}, {GLFW_KEY_3, kControl}}),
        viewRow<AxisView::Top>(Command::ViewTop, "Top", "Look down -y", {{GLFW_KEY_KP_7}, {GLFW_KEY_7}}),
        viewRow<AxisView::Bottom>(Command::ViewBottom, "Bottom", "Look up +y",
                                  {{GLFW_KEY_KP_7, kControl}, {GLFW_KEY_7, kControl}}),
        orbitRow<-15, 0>(Command::OrbitLeft, "Orbit Left", "Turn the view 15 degrees",
                         {{GLFW_KEY_KP_4}, {GLFW_KEY_LEFT}}),
        orbitRow<15, 0>(Command::OrbitRight, "Orbit Right", "Turn the view 15 degrees",
                        {{GLFW_KEY_KP_6}, {GLFW_KEY_RIGHT}}),
        orbitRow<0, -15>(Command::OrbitUp, "Orbit Up", "Tilt the view 15 degrees", {{GLFW_KEY_KP_8}, {GLFW_KEY_UP}}),
        orbitRow<0, 15>(Command::OrbitDown, "Orbit Down", "Tilt the view 15 degrees",
                        {{GLFW_KEY_KP_2}, {GLFW_KEY_DOWN}}),
        {Command::ZoomIn,
         "Zoom In",
         "Move closer",
         {{GLFW_KEY_KP_ADD}, {GLFW_KEY_EQUAL}},
         nullptr,
         [](App& a) { a.camera().zoom(1.25); }},
        {Command::ZoomOut,
         "Zoom Out",
         "Move away",
         {{GLFW_KEY_KP_SUBTRACT}, {GLFW_KEY_MINUS}},
         nullptr,
         [](App& a) { a.camera().zoom(0.8); }},
        {Command::NextShading,
         "Next Matcap",
         "Clay, white, red wax, lit",
         {{GLFW_KEY_M, kShift}},
         nullptr,
         [](App& a) { a.look().setShading(Shading((int(a.look().shading()) + 1) % 4)); }},
        {Command::ToggleFlat,
         "Flat Shading",
         "Facets instead of smooth normals",
         {{GLFW_KEY_L}},
         nullptr,
         [](App& a) { a.look().setFlat(!a.look().flat()); }},
        {Command::ToggleWireframe,
         "Wireframe",
         "Draw the triangles' edges",
         {{GLFW_KEY_W}},
         nullptr,
         [](App& a) { a.look().setWireframe(!a.look().wireframe()); }},
        {Command::ToggleScales,
         "Scales",
         "Small discs on the surface at its samples, turned to its normal: a quick view",
         {{GLFW_KEY_V}},
         nullptr,
         [](App& a) { a.mView.scales().setShown(!a.mView.scales().shown()); }},
        {Command::ToggleGhost,
         "Target Ghost",
         "Show or hide the target shape, drawn translucent",
         {{GLFW_KEY_H}},
         [](const App& a) {
             return a.mBrush.target.shape ? std::string()
                                          : std::string("no target loaded: File > Load Target (Ctrl+T) loads one");
         },
         [](App& a) { a.mView.ghost().setShown(!a.mView.ghost().shown()); }},
        {Command::ToggleXRay,
         "X-Ray",
         "See-through clay: what lies inside shows (on while placing primitives)",
         {{GLFW_KEY_Z, kAlt}},
         nullptr,
         [](App& a) { a.look().setXRay(!a.look().xray()); }},
        {Command::ToggleTrackball,
         "Trackball Orbit",
         "Free rotation instead of turntable",
         {{GLFW_KEY_R, kShift}},
         nullptr,
         [](App& a) { toggle(a.camera().trackball); }},
        {Command::ToggleHelp,
         "Help",
         "Keys and mouse",
         {{GLFW_KEY_F1}},
         nullptr,
         [](App& a) { toggle(a.mDialogs.help); }},
        {Command::Confirm,
         "Apply",
         "Applies the open panel: the import, the primitives' bake, the morph frame shown",
         {{GLFW_KEY_ENTER}, {GLFW_KEY_KP_ENTER}},
         accepting,
         [](App& a) { a.acceptMode(); }},
        {Command::Cancel,
         "Cancel",
         "Cancels the running job, else closes the open panel (the document stays as it was)",
         {{GLFW_KEY_ESCAPE}},
         nullptr,
         [](App& a) {
             if (a.mJobs.running()) a.mJobs.cancel();
             else a.closeMode();
         }},
        {Command::AnswerSave,
         "Save",
         "Unsaved changes: save them, then go on",
         {{GLFW_KEY_S}},
         unsavedOpen,
         [](App& a) { a.answerUnsaved(true, false); },
         Scope::Dialog},
        {Command::AnswerDiscard,
         "Discard",
         "Unsaved changes: go on without saving them; Recover: delete the autosave",
         {{GLFW_KEY_D}},
         [](const App& a) { return a.mDialogs.recovery ? std::string() : unsavedOpen(a); },
         [](App& a) {
             if (a.mDialogs.afterUnsaved) a.answerUnsaved(false, true);
             else a.recover(false);
         },
         Scope::Dialog},
        {Command::AnswerRecover,
         "Recover",
         "Recover: open the autosave of the work that was not saved",
         {{GLFW_KEY_R}},
         recoveryOpen,
         [](App& a) { a.recover(true); },
         Scope::Dialog},
        gridRow<1>(),
        gridRow<2>(),
        gridRow<3>(),
        gridRow<4>(),
        gridRow<5>(),
        gridRow<6>(),
        gridRow<7>(),
        gridRow<8>(),
        gridRow<9>(),
        {Command::DialogConfirm,
         "OK",
         "Dialogs: confirm the prompt; dismiss an error",
         {{GLFW_KEY_ENTER}, {GLFW_KEY_KP_ENTER}},
         [](const App& a) {
             if (!a.mDialogs.error.empty() || a.mDialogs.confirmable()) return std::string();
             return std::string("nothing to confirm: answer the dialog's question");
         },
         [](App& a) {
             if (!a.mDialogs.error.empty()) a.mDialogs.error.clear();
             else a.confirmPrompt();
         },
         Scope::Dialog},
        {Command::DialogCancel,
         "Close",
         "Dialogs: close without doing anything (unsaved changes: go back)",
         {{GLFW_KEY_ESCAPE}},
         [](const App& a) {
             return a.mDialogs.recovery && a.mDialogs.error.empty()
                        ? std::string("recover the autosave (R) or discard it (D)")
                        : std::string();
         },
         [](App& a) {
             Dialogs& d = a.mDialogs;
             if (!d.error.empty()) d.error.clear();
             else if (d.gridChoice) a.openChosenGrid(std::nullopt);
             else if (d.afterUnsaved) a.answerUnsaved(false, false);
             else d.prompt = Dialogs::Prompt::None;
         },
         Scope::Dialog},
    };
    for (const AppRow& row : rows) {
        std::function<std::string()> blocked;
        if (row.blocked) blocked = [this, rule = row.blocked] { return rule(*this); };
        mCommands.add({row.command, row.label, row.help, row.chords, std::move(blocked),
                       [this, action = row.run] { action(*this); }, row.scope});
    }
}

}  // namespace sculpt::ui
