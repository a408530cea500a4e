// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file commands.h
/// @brief Everything a key, a menu item or a button can ask for. Each is registered once, by
///        the part that owns it, in the window's CommandRegistry, which feeds the keys, the menus
///        (and when they are greyed out), the tooltips, the Help panel and SculptApp::execute.

#include <functional>
#include <string>
#include <vector>

namespace sculpt::ui {

enum class Command {
    ToolAdd,
    ToolCarve,
    ToolInflate,
    ToolDeflate,
    ToolSmooth,
    ToolFlatten,
    ToolGrab,
    ToolPinch,
    ToolFollow,
    ToolPrimitive,
    ToolMask,
    ToolLassoCut,
    ToolBoxCut,
    ToolLineCut,
    ToolBoxMask,
    ToolLassoMask,
    RadiusDrag,
    StrengthDrag,
    RadiusSmaller,
    RadiusLarger,
    SymmetryX,
    SymmetryY,
    SymmetryZ,
    Undo,
    Redo,
    New,
    Open,
    Save,
    SaveAs,
    ExportMesh,
    ExportLabels,
    SaveStrokes,
    Import,
    ApplyImport,
    AddPrimitive,
    RemovePrimitive,
    BakePrimitives,
    LoadScene,
    SaveScene,
    LoadTarget,
    Quit,
    InvertMask,
    ClearMask,
    BlurMask,
    SharpenMask,
    GrowMask,
    ShrinkMask,
    MaskIsland,
    MaskCavities,
    MaskThinWalls,
    SmoothModel,
    OffsetModel,
    HollowModel,
    RemoveIslands,
    KeepIsland,
    DeleteIsland,
    DrillDrainHole,
    MorphTo,
    MorphPlay,
    StepUp,
    StepDown,
    MorphKeep,
    MorphExport,
    FrameModel,
    ViewFront,
    ViewBack,
    ViewRight,
    ViewLeft,
    ViewTop,
    ViewBottom,
    OrbitLeft,
    OrbitRight,
    OrbitUp,
    OrbitDown,
    ZoomIn,
    ZoomOut,
    NextShading,
    ToggleFlat,
    ToggleWireframe,
    ToggleScales,
    ToggleGhost,
    ToggleXRay,
    ToggleSlices,
    CycleClipPlane,
    ClipPlaneForward,
    ClipPlaneBack,
    FlipClipPlane,
    ToggleTrackball,
    ToggleHelp,
    Confirm,
    Cancel,
    PiecesMode,
    MovePiece,
    RotatePiece,
    ScalePiece,
    TogglePush,
    ApplyPlacement,
    SoloPiece,
    DuplicatePiece,
    DeletePiece,
    SplitPiece,
    MergePieces,
    // The dialogs' answers (Scope::Dialog).
    AnswerSave,
    AnswerDiscard,
    AnswerRecover,
    ChooseGrid1,  // ... ChooseGrid9: the level set with this number in "Which level set?"
    ChooseGrid2,
    ChooseGrid3,
    ChooseGrid4,
    ChooseGrid5,
    ChooseGrid6,
    ChooseGrid7,
    ChooseGrid8,
    ChooseGrid9,
    DialogConfirm,
    DialogCancel,  // the last: kCommandCount counts up to it
};

/// The number of commands: every value below it has one row in the table.
constexpr int kCommandCount = int(Command::DialogCancel) + 1;

/// Where a command's keys work: in the view, in pieces mode (before the view's), or in the dialog
/// on top of it (which takes every key while it is open). A chord is bound at most once per scope.
enum class Scope { View, Dialog, Pieces };

/// A key with exactly these modifiers (Shift, Ctrl, Alt).
struct Chord {
    int key;  ///< GLFW key code
    int mods = 0;
};

/// One command, registered by the part that owns it (a tool, a mode, the window): what menus,
/// tooltips and Help show, its keys, when it can run (the menus grey it out by the same rule) and
/// what it does.
struct CommandRow {
    Command command;
    const char* label;
    const char* help;
    std::vector<Chord> chords;
    /// Why it cannot run now ("nothing to undo"), or "" when it can; empty: it always can.
    std::function<std::string()> blocked;
    std::function<void()> run;
    Scope scope = Scope::View;
};

}  // namespace sculpt::ui
