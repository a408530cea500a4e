// SPDX-License-Identifier: Apache-2.0
// The View menu's commands: framing, the axis views and orbit steps (Blender's numpad), zoom,
// the clay's looks, the target's ghost, the trackball, the clip plane, and Help. Navigation follows Blender's
// sculpt mode where it has a key.

#include "ui/input/input_event.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace sculpt::ui {

namespace {

void addCameraCommands(CommandRegistry& commands, PanelHost& host)
{
    CameraControl& camera = host.camera();
    commands.add({Command::FrameModel,
                  "Frame Model",
                  "Fit the model in the view",
                  {{GLFW_KEY_HOME}, {GLFW_KEY_KP_DECIMAL}},
                  nullptr,
                  [&host] { host.view().frameAll(host.document()); }});
    struct Axis {
        Command command;
        const char* label;
        const char* help;
        int key, keypad, mods;
        AxisView view;
    };
    const Axis axes[] = {
        {Command::ViewFront, "Front", "Look along -z", GLFW_KEY_1, GLFW_KEY_KP_1, 0, AxisView::Front},
        {Command::ViewBack, "Back", "Look along +z", GLFW_KEY_1, GLFW_KEY_KP_1, kControl, AxisView::Back},
        {Command::ViewRight, "Right", "Look along -x", GLFW_KEY_3, GLFW_KEY_KP_3, 0, AxisView::Right},
        {Command::ViewLeft, "Left", "Look along +x", GLFW_KEY_3, GLFW_KEY_KP_3, kControl, AxisView::Left},
        {Command::ViewTop, "Top", "Look down -y", GLFW_KEY_7, GLFW_KEY_KP_7, 0, AxisView::Top},
        {Command::ViewBottom, "Bottom", "Look up +y", GLFW_KEY_7, GLFW_KEY_KP_7, kControl, AxisView::Bottom},
    };
    for (const Axis& a : axes)
        commands.add(
            {a.command, a.label, a.help, {{a.keypad, a.mods}, {a.key, a.mods}}, nullptr, [&camera, view = a.view] {
                 camera.axisView(view);
             }});
    struct Orbit {
        Command command;
        const char* label;
        const char* help;
        int keypad, arrow;
        double yaw, pitch;
    };
    const Orbit orbits[] = {
        {Command::OrbitLeft, "Orbit Left", "Turn the view 15 degrees", GLFW_KEY_KP_4, GLFW_KEY_LEFT, -15, 0},
        {Command::OrbitRight, "Orbit Right", "Turn the view 15 degrees", GLFW_KEY_KP_6, GLFW_KEY_RIGHT, 15, 0},
        {Command::OrbitUp, "Orbit Up", "Tilt the view 15 degrees", GLFW_KEY_KP_8, GLFW_KEY_UP, 0, -15},
        {Command::OrbitDown, "Orbit Down", "Tilt the view 15 degrees", GLFW_KEY_KP_2, GLFW_KEY_DOWN, 0, 15},
    };
    for (const Orbit& o : orbits)
        commands.add(
            {o.command, o.label, o.help, {{o.keypad}, {o.arrow}}, nullptr, [&camera, yaw = o.yaw, pitch = o.pitch] {
                 camera.orbitDegrees(yaw, pitch);
             }});
    commands.add({Command::ZoomIn, "Zoom In", "Move closer", {{GLFW_KEY_KP_ADD}, {GLFW_KEY_EQUAL}}, nullptr, [&camera] {
                      camera.zoom(1.25);
                  }});
    commands.add(
        {Command::ZoomOut, "Zoom Out", "Move away", {{GLFW_KEY_KP_SUBTRACT}, {GLFW_KEY_MINUS}}, nullptr, [&camera] {
             camera.zoom(0.8);
         }});
    commands.add({Command::ToggleTrackball,
                  "Trackball Orbit",
                  "Free rotation instead of turntable",
                  {{GLFW_KEY_R, kShift}},
                  nullptr,
                  [&camera] { camera.trackball = !camera.trackball; }});
}

void addLookCommands(CommandRegistry& commands, PanelHost& host)
{
    SurfaceLook& look = host.look();
    DocumentView& view = host.view();
    commands.add(
        {Command::NextShading, "Next Matcap", "Clay, white, red wax, lit", {{GLFW_KEY_M, kShift}}, nullptr, [&look] {
             look.setShading(Shading((int(look.shading()) + 1) % 4));
         }});
    commands.add(
        {Command::ToggleFlat, "Flat Shading", "Facets instead of smooth normals", {{GLFW_KEY_L}}, nullptr, [&look] {
             look.setFlat(!look.flat());
         }});
    commands.add({Command::ToggleWireframe, "Wireframe", "Draw the triangles' edges", {{GLFW_KEY_W}}, nullptr, [&look] {
                      look.setWireframe(!look.wireframe());
                  }});
    commands.add({Command::ToggleScales,
                  "Scales",
                  "Small discs on the surface at its samples, turned to its normal: a quick view",
                  {{GLFW_KEY_V}},
                  nullptr,
                  [&view] { view.scales().setShown(!view.scales().shown()); }});
    commands.add({Command::ToggleGhost,
                  "Target Ghost",
                  "Show or hide the target shape, drawn translucent",
                  {{GLFW_KEY_H}},
                  [&host] {
                      return host.brush().target.shape
                                 ? std::string()
                                 : std::string("no target loaded: File > Load Target (Ctrl+T) loads one");
                  },
                  [&view] { view.ghost().setShown(!view.ghost().shown()); }});
    commands.add({Command::ToggleXRay,
                  "X-Ray",
                  "See-through clay: what lies inside shows (on while placing primitives)",
                  {{GLFW_KEY_Z, kAlt}},
                  nullptr,
                  [&look] { look.setXRay(!look.xray()); }});
    commands.add({Command::ToggleHelp, "Help", "Keys and mouse", {{GLFW_KEY_F1}}, nullptr, [&host] {
                      host.dialogs().help = !host.dialogs().help;
                  }});
}

/// The clip plane's step: a hundredth of the model, never under a voxel.
double clipStep(PanelHost& host)
{
    const openvdb::BBoxd box = host.view().worldBox(host.document());
    const double size = box.empty() ? 0.0 : (box.max() - box.min()).length();
    return std::max(host.document().session().field().voxelSize(), 0.01 * size);
}

void addClipCommands(CommandRegistry& commands, PanelHost& host)
{
    SliceViews& slices = host.view().slices();
    commands.add({Command::ToggleSlices,
                  "Slices",
                  "The kept scan's axial, coronal and sagittal slices through a cursor, with the pieces' contours: "
                  "left click or drag sets the cursor (a click on the model too), right drag the window and level, "
                  "the wheel steps",
                  {{GLFW_KEY_V, kAlt}},
                  [&host] {
                      return host.document().keptScan()
                                 ? std::string()
                                 : std::string("this document keeps no scan: import one (File > Import) to see its "
                                               "slices");
                  },
                  [&slices] { slices.setShown(!slices.shown()); }});
    ClipPlane& clip = host.view().clip();
    commands.add({Command::CycleClipPlane,
                  "Clip Plane",
                  "Cut the view across x, y, z or the view direction, then off: the cut is capped with the exact "
                  "section, and strokes land on it",
                  {{GLFW_KEY_C, kAlt}},
                  nullptr,
                  [&host, &clip] {
                      const openvdb::Vec3d centre = host.view().worldBox(host.document()).getCenter();
                      const Viewport& viewport = host.view().viewport();
                      const glm::dvec3 ahead =
                          viewport.rayThrough(0.5 * viewport.width(), 0.5 * viewport.height()).direction;
                      clip.setAxis(ClipAxis((int(clip.axis()) + 1) % 5), ahead, {centre.x(), centre.y(), centre.z()});
                  }});
    const auto needsPlane = [&clip] {
        return clip.axis() == ClipAxis::Off ? std::string("the clip plane is off: View > Clip Plane (Alt+C)")
                                            : std::string();
    };
    commands.add({Command::ClipPlaneForward,
                  "Clip Plane Forward",
                  "Move the clip plane along its normal",
                  {{GLFW_KEY_UP, kAlt}},
                  needsPlane,
                  [&host, &clip] { clip.move(clipStep(host)); }});
    commands.add({Command::ClipPlaneBack,
                  "Clip Plane Back",
                  "Move the clip plane against its normal",
                  {{GLFW_KEY_DOWN, kAlt}},
                  needsPlane,
                  [&host, &clip] { clip.move(-clipStep(host)); }});
    commands.add({Command::FlipClipPlane,
                  "Flip Clip Side",
                  "Hide the other side of the clip plane",
                  {{GLFW_KEY_F, kAlt}},
                  needsPlane,
                  [&clip] { clip.setFlipped(!clip.flipped()); }});
}

}  // namespace

void addViewCommands(CommandRegistry& commands, PanelHost& host)
{
    addCameraCommands(commands, host);
    addLookCommands(commands, host);
    addClipCommands(commands, host);
}

}  // namespace sculpt::ui
