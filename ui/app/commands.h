#pragma once
/// @file commands.h
/// @brief Everything a key, a menu item or a button can ask for, and the keys bound to each:
///        one table feeds the key handling, the menus' hints, the tooltips and the Help panel.

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
    SmoothModel,
    OffsetModel,
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
    ToggleTrackball,
    ToggleHelp,
    Confirm,
    Cancel,
};

struct KeyBinding {
    int key;   ///< GLFW key code
    int mods;  ///< exactly these modifiers (Shift, Ctrl, Alt)
    Command command;
};

struct CommandInfo {
    Command command;
    const char* label;
    const char* help;
};

/// Every binding; a command may have several (Ctrl+Shift+Z and Ctrl+Y redo).
const std::vector<KeyBinding>& keyBindings();
const CommandInfo& commandInfo(Command command);
const std::vector<CommandInfo>& allCommands();
/// "Ctrl+Shift+Z, Ctrl+Y" for a command; "" if it has no key.
std::string shortcutText(Command command);
/// The command bound to this key and modifiers, if any.
bool commandForKey(int key, int mods, Command& command);

}  // namespace sculpt::ui
