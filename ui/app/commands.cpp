#include "ui/app/commands.h"

#include "ui/input/input_event.h"

#include <GLFW/glfw3.h>

#include <utility>

namespace sculpt::ui {

namespace {

constexpr int kCtrlShift = kControl | kShift;

/// A key as menus and Help show it: "[" rather than the recordings' "LeftBracket".
std::string shownKeyName(int key)
{
    static const std::vector<std::pair<std::string, std::string>> shown = {{"LeftBracket", "["},
                                                                           {"RightBracket", "]"},
                                                                           {"KPDecimal", "Numpad ."},
                                                                           {"KPEnter", "Numpad Enter"},
                                                                           {"Escape", "Esc"}};
    const std::string name = keyName(key);
    for (const auto& [recorded, display] : shown) {
        if (name == recorded) return display;
    }
    return name;
}

}  // namespace

const std::vector<KeyBinding>& keyBindings()
{
    // Tools and navigation after Blender's sculpt mode where it has a key; symmetry on X/Y/Z.
    static const std::vector<KeyBinding> bindings = {
        {GLFW_KEY_A, 0, Command::ToolAdd},
        {GLFW_KEY_C, 0, Command::ToolCarve},
        {GLFW_KEY_I, 0, Command::ToolInflate},
        {GLFW_KEY_D, 0, Command::ToolDeflate},
        {GLFW_KEY_S, 0, Command::ToolSmooth},
        {GLFW_KEY_T, 0, Command::ToolFlatten},
        {GLFW_KEY_G, 0, Command::ToolGrab},
        {GLFW_KEY_P, 0, Command::ToolPinch},
        {GLFW_KEY_O, 0, Command::ToolFollow},
        {GLFW_KEY_B, 0, Command::ToolPrimitive},
        {GLFW_KEY_F, 0, Command::RadiusDrag},
        {GLFW_KEY_F, kShift, Command::StrengthDrag},
        {GLFW_KEY_LEFT_BRACKET, 0, Command::RadiusSmaller},
        {GLFW_KEY_RIGHT_BRACKET, 0, Command::RadiusLarger},
        {GLFW_KEY_X, 0, Command::SymmetryX},
        {GLFW_KEY_Y, 0, Command::SymmetryY},
        {GLFW_KEY_Z, 0, Command::SymmetryZ},
        {GLFW_KEY_Z, kControl, Command::Undo},
        {GLFW_KEY_Z, kCtrlShift, Command::Redo},
        {GLFW_KEY_Y, kControl, Command::Redo},
        {GLFW_KEY_N, kControl, Command::New},
        {GLFW_KEY_O, kControl, Command::Open},
        {GLFW_KEY_S, kControl, Command::Save},
        {GLFW_KEY_S, kCtrlShift, Command::SaveAs},
        {GLFW_KEY_E, kControl, Command::ExportMesh},
        {GLFW_KEY_T, kControl, Command::LoadTarget},
        {GLFW_KEY_I, kControl, Command::Import},
        {GLFW_KEY_A, kShift, Command::AddPrimitive},
        {GLFW_KEY_DELETE, 0, Command::RemovePrimitive},
        {GLFW_KEY_O, kControl | kAlt, Command::LoadScene},
        {GLFW_KEY_S, kControl | kAlt, Command::SaveScene},
        {GLFW_KEY_Q, kControl, Command::Quit},
        {GLFW_KEY_S, kAlt, Command::SmoothModel},
        {GLFW_KEY_O, kAlt, Command::OffsetModel},
        {GLFW_KEY_M, kAlt, Command::MorphTo},
        {GLFW_KEY_SPACE, 0, Command::MorphPlay},
        {GLFW_KEY_PAGE_UP, 0, Command::StepUp},
        {GLFW_KEY_PAGE_DOWN, 0, Command::StepDown},
        {GLFW_KEY_K, 0, Command::MorphKeep},
        {GLFW_KEY_E, kShift, Command::MorphExport},
        {GLFW_KEY_HOME, 0, Command::FrameModel},
        {GLFW_KEY_KP_DECIMAL, 0, Command::FrameModel},
        {GLFW_KEY_KP_1, 0, Command::ViewFront},
        {GLFW_KEY_1, 0, Command::ViewFront},
        {GLFW_KEY_KP_1, kControl, Command::ViewBack},
        {GLFW_KEY_1, kControl, Command::ViewBack},
        {GLFW_KEY_KP_3, 0, Command::ViewRight},
        {GLFW_KEY_3, 0, Command::ViewRight},
        {GLFW_KEY_KP_3, kControl, Command::ViewLeft},
        {GLFW_KEY_3, kControl, Command::ViewLeft},
        {GLFW_KEY_KP_7, 0, Command::ViewTop},
        {GLFW_KEY_7, 0, Command::ViewTop},
        {GLFW_KEY_KP_7, kControl, Command::ViewBottom},
        {GLFW_KEY_7, kControl, Command::ViewBottom},
        {GLFW_KEY_KP_4, 0, Command::OrbitLeft},
        {GLFW_KEY_LEFT, 0, Command::OrbitLeft},
        {GLFW_KEY_KP_6, 0, Command::OrbitRight},
        {GLFW_KEY_RIGHT, 0, Command::OrbitRight},
        {GLFW_KEY_KP_8, 0, Command::OrbitUp},
        {GLFW_KEY_UP, 0, Command::OrbitUp},
        {GLFW_KEY_KP_2, 0, Command::OrbitDown},
        {GLFW_KEY_DOWN, 0, Command::OrbitDown},
        {GLFW_KEY_KP_ADD, 0, Command::ZoomIn},
        {GLFW_KEY_EQUAL, 0, Command::ZoomIn},
        {GLFW_KEY_KP_SUBTRACT, 0, Command::ZoomOut},
        {GLFW_KEY_MINUS, 0, Command::ZoomOut},
        {GLFW_KEY_M, 0, Command::NextShading},
        {GLFW_KEY_L, 0, Command::ToggleFlat},
        {GLFW_KEY_W, 0, Command::ToggleWireframe},
        {GLFW_KEY_V, 0, Command::ToggleScales},
        {GLFW_KEY_H, 0, Command::ToggleGhost},
        {GLFW_KEY_Z, kAlt, Command::ToggleXRay},
        {GLFW_KEY_R, kShift, Command::ToggleTrackball},
        {GLFW_KEY_F1, 0, Command::ToggleHelp},
        {GLFW_KEY_ENTER, 0, Command::Confirm},
        {GLFW_KEY_KP_ENTER, 0, Command::Confirm},
        {GLFW_KEY_ESCAPE, 0, Command::Cancel},
    };
    return bindings;
}

const std::vector<CommandInfo>& allCommands()
{
    static const std::vector<CommandInfo> commands = {
        {Command::ToolAdd, "Add", "Builds clay up (Ctrl: carve)"},
        {Command::ToolCarve, "Carve", "Digs clay away (Ctrl: add)"},
        {Command::ToolInflate, "Inflate", "Swells the surface along its normal (Ctrl: deflate)"},
        {Command::ToolDeflate, "Deflate", "Shrinks the surface along its normal (Ctrl: inflate)"},
        {Command::ToolSmooth, "Smooth", "Evens out bumps (hold Shift with any tool)"},
        {Command::ToolFlatten, "Flatten", "Presses the surface onto its mean plane"},
        {Command::ToolGrab, "Grab", "Drags the clay under the brush along with the mouse"},
        {Command::ToolPinch, "Pinch", "Pulls the surface towards the stroke: sharp creases"},
        {Command::ToolFollow, "Follow", "Pulls the surface under the brush onto the target shape (Ctrl+T loads one)"},
        {Command::ToolPrimitive, "Blob", "Stamps a soft blob (Ctrl: carves one)"},
        {Command::RadiusDrag, "Radius", "Then move the mouse to size the brush; click or Enter to keep, Esc to undo"},
        {Command::StrengthDrag, "Strength", "Then move the mouse to set the strength"},
        {Command::RadiusSmaller, "Smaller brush", "Radius x 0.8"},
        {Command::RadiusLarger, "Larger brush", "Radius x 1.25"},
        {Command::SymmetryX, "Mirror X", "Mirror strokes across the plane x = 0"},
        {Command::SymmetryY, "Mirror Y", "Mirror strokes across the plane y = 0"},
        {Command::SymmetryZ, "Mirror Z", "Mirror strokes across the plane z = 0"},
        {Command::Undo, "Undo", "Undo the last stroke"},
        {Command::Redo, "Redo", "Redo the stroke undone last"},
        {Command::New, "New...", "A new document from a sphere, box or torus"},
        {Command::Open, "Open...", "Open a .vdb document"},
        {Command::Save, "Save", "Save the document"},
        {Command::SaveAs, "Save As...", "Save the document under a new name"},
        {Command::ExportMesh, "Export Mesh...", "Write the surface as PLY, OBJ or STL"},
        {Command::SaveStrokes, "Save Strokes...", "Write this session's strokes for `sculpt apply`"},
        {Command::Import, "Import...",
         "A scan (NIfTI, NRRD, MetaImage, DICOM) or a mesh: preview the surface, then a new document, or "
         "union/difference with this one"},
        {Command::ApplyImport, "Apply Import", "Import with the panel's settings (a job)"},
        {Command::AddPrimitive, "Add Primitive",
         "Opens the Primitives panel and adds a blob where the pointer is on the surface (click or drag to place it)"},
        {Command::RemovePrimitive, "Remove Primitive", "Removes the selected primitive (Primitives panel)"},
        {Command::BakePrimitives, "Bake Primitives",
         "Combines the panel's primitives into the model by the scene's operation (one undo step)"},
        {Command::LoadScene, "Load Scene...", "Opens a primitive scene file in the Primitives panel"},
        {Command::SaveScene, "Save Scene...", "Writes the panel's primitives as a scene file for `sculpt build`"},
        {Command::LoadTarget, "Load Target...",
         "A document, scan or mesh for the follow brush and the morph, shown as a ghost (a job)"},
        {Command::Quit, "Quit", "Close Sculpt (asks first if there are unsaved changes)"},
        {Command::SmoothModel, "Smooth Model...",
         "Mean-curvature flow over the whole model, as a job (Esc cancels; one undo step)"},
        {Command::OffsetModel, "Offset Model...",
         "Grow or shrink the whole model along its normal, as a job (Esc cancels; one undo step)"},
        {Command::MorphTo, "Morph To...",
         "Morph the model into a target document, scan or mesh, as a job; then play and keep frames"},
        {Command::MorphPlay, "Play/Pause Morph", "Play the morph's frames (Morph panel)"},
        {Command::StepUp, "Step Up", "Morph: the previous frame; Import: the iso-value up by 1% of the range"},
        {Command::StepDown, "Step Down", "Morph: the next frame; Import: the iso-value down by 1% of the range"},
        {Command::MorphKeep, "Keep Frame", "Make the frame shown the document (one undo step)"},
        {Command::MorphExport, "Export Frames...", "Write the morph's frames as DIR/frame_0000.vdb ..."},
        {Command::FrameModel, "Frame Model", "Fit the model in the view"},
        {Command::ViewFront, "Front", "Look along -z"},
        {Command::ViewBack, "Back", "Look along +z"},
        {Command::ViewRight, "Right", "Look along -x"},
        {Command::ViewLeft, "Left", "Look along +x"},
        {Command::ViewTop, "Top", "Look down -y"},
        {Command::ViewBottom, "Bottom", "Look up +y"},
        {Command::OrbitLeft, "Orbit Left", "Turn the view 15 degrees"},
        {Command::OrbitRight, "Orbit Right", "Turn the view 15 degrees"},
        {Command::OrbitUp, "Orbit Up", "Tilt the view 15 degrees"},
        {Command::OrbitDown, "Orbit Down", "Tilt the view 15 degrees"},
        {Command::ZoomIn, "Zoom In", "Move closer"},
        {Command::ZoomOut, "Zoom Out", "Move away"},
        {Command::NextShading, "Next Matcap", "Clay, white, red wax, lit"},
        {Command::ToggleFlat, "Flat Shading", "Facets instead of smooth normals"},
        {Command::ToggleWireframe, "Wireframe", "Draw the triangles' edges"},
        {Command::ToggleScales, "Scales",
         "Small discs on the surface at its samples, turned to its normal: a quick view"},
        {Command::ToggleXRay, "X-Ray", "See-through clay: what lies inside shows (on while placing primitives)"},
        {Command::ToggleGhost, "Target Ghost", "Show or hide the target shape, drawn translucent"},
        {Command::ToggleTrackball, "Trackball Orbit", "Free rotation instead of turntable"},
        {Command::ToggleHelp, "Help", "Keys and mouse"},
        {Command::Confirm, "Apply", "Applies the open panel: the import, the primitives' bake, the morph frame shown"},
        {Command::Cancel, "Cancel",
         "Cancels the running job, else closes the open panel (the document stays as it was)"},
    };
    return commands;
}

const CommandInfo& commandInfo(Command command)
{
    for (const CommandInfo& info : allCommands()) {
        if (info.command == command) return info;
    }
    return allCommands().front();
}

std::string shortcutText(Command command)
{
    std::string text;
    for (const KeyBinding& b : keyBindings()) {
        if (b.command != command) continue;
        if (!text.empty()) text += ", ";
        if (b.mods & kControl) text += "Ctrl+";
        if (b.mods & kShift) text += "Shift+";
        if (b.mods & kAlt) text += "Alt+";
        text += shownKeyName(b.key);
    }
    return text;
}

bool commandForKey(int key, int mods, Command& command)
{
    const int relevant = mods & (kShift | kControl | kAlt);
    for (const KeyBinding& b : keyBindings()) {
        if (b.key == key && b.mods == relevant) {
            command = b.command;
            return true;
        }
    }
    return false;
}

}  // namespace sculpt::ui
