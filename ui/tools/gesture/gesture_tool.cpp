// SPDX-License-Identifier: Apache-2.0
#include "ui/tools/gesture/gesture_tool.h"

#include "sculpt/session/document.h"
#include "ui/commands/command_registry.h"
#include "ui/input/input_event.h"
#include "ui/tools/tool_box.h"
#include "ui/tools/tool_host.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>

namespace sculpt::ui {

void GestureTool::addCommands(CommandRegistry& registry, ToolBox& box)
{
    using Shape = CutGesture::Shape;
    const struct {
        Command command;
        Shape shape;
        bool masks;
        const char* label;
        const char* help;
        Chord chord;
    } gestures[] = {
        {Command::ToolLassoCut,
         Shape::Lasso,
         false,
         "Lasso Cut",
         "Draw around what to cut away, through the model along the view (Ctrl: fill it with clay)",
         {GLFW_KEY_J}},
        {Command::ToolBoxCut,
         Shape::Box,
         false,
         "Box Cut",
         "Drag a box to cut away along the view (Ctrl: fill it)",
         {GLFW_KEY_J, kShift}},
        {Command::ToolLineCut,
         Shape::Line,
         false,
         "Line Cut",
         "Drag a line: what lies to its right, as you see it, is cut away",
         {GLFW_KEY_J, kAlt}},
        {Command::ToolBoxMask,
         Shape::Box,
         true,
         "Box Mask",
         "Drag a box: the clay in it, through the model along the view, is masked (Ctrl: unmasked)",
         {GLFW_KEY_B, kShift}},
        {Command::ToolLassoMask,
         Shape::Lasso,
         true,
         "Lasso Mask",
         "Draw around the clay to mask, through the model along the view (Ctrl: unmask it)",
         {GLFW_KEY_B, kAlt}},
    };
    for (const auto& g : gestures) {
        registry.add({g.command, g.label, g.help, {g.chord}, {}, [this, &box, shape = g.shape, masks = g.masks] {
                          choose(shape, masks);
                          box.choose(*this);
                      }});
    }
}

void GestureTool::choose(CutGesture::Shape shape, bool masks)
{
    mShape = shape;
    mMasks = masks;
}

bool GestureTool::press(const InputEvent& event)
{
    if (mCut.active()) return true;  // another button while drawing: it goes on
    if (mHost.busy()) return false;
    mMods = event.mods | mHost.heldMods();
    const glm::dvec2 at = mHost.pointer();
    const std::optional<SurfaceHit> hit = mHost.pickAt(at.x, at.y);
    const glm::dvec3 focus = hit ? mHost.inWorld(*hit).position : mHost.camera().focalPoint();
    mNear = -(mHost.viewport().viewFromWorld() * glm::dvec4(focus, 1.0)).z;
    mCut.begin(mShape, at.x, at.y);
    return true;
}

void GestureTool::drag(const InputEvent& event) { mCut.extend(event.x, event.y); }

void GestureTool::release(const InputEvent& event)
{
    if (event.button == kLeftButton) land();
}

bool GestureTool::key(const InputEvent& event)
{
    if (event.key != GLFW_KEY_ESCAPE) return false;
    mCut.clear();
    mHost.notify(std::string(mMasks ? "mask" : "cut") + " dropped");
    return true;
}

void GestureTool::land()
{
    const bool ctrl = (mMods & kControl) != 0, fill = ctrl && !mMasks;
    const BrushOptions& brush = mHost.brush();
    // A fill needs a depth: twice the brush's radius unless one is set.
    const double depth = mDepth > 0.0 ? mDepth : fill ? 2.0 * brush.radius : 0.0;
    const double nearDepth = depth > 0.0 ? mNear : -std::numeric_limits<double>::infinity();
    const double farDepth = depth > 0.0 ? mNear + depth : std::numeric_limits<double>::infinity();
    std::optional<ViewPrism> prism = mCut.prism(mHost.viewport(), nearDepth, farDepth, brush.symmetry);
    mCut.clear();
    if (!prism || mHost.busy()) return;
    // The piece's voxels are in its own world: view from it = view from the world after its placement.
    const Document& document = mHost.document();
    prism->viewFromWorld = document.pieces()[document.activePiece()].look.placement * prism->viewFromWorld;
    const std::string slab = depth > 0.0 ? " (slab)" : "";
    if (mMasks) {
        MaskSelection selection;
        selection.prism = *prism;
        selection.erase = ctrl;
        const char* shape = mShape == CutGesture::Shape::Box ? " box" : " lasso";
        return mHost.workspace().startEdit(
            maskSelectionEdit(selection, std::string(ctrl ? "unmask" : "mask") + shape + slab));
    }
    mHost.workspace().autosaveNow();
    mHost.workspace().startEdit(
        prismEdit(*prism, fill ? PrismMode::Fill : PrismMode::Cut, std::string(fill ? "fill" : "cut") + slab));
}

void GestureTool::drawOverlay() const
{
    if (!mCut.active()) return;
    std::vector<ImVec2> points;
    for (const glm::dvec2& p : mCut.outline()) points.emplace_back(float(p.x), float(p.y));
    const bool ctrl = ((mMods | mHost.heldMods()) & kControl) != 0;
    const ImU32 colour = mMasks ? (ctrl ? IM_COL32(230, 230, 230, 230) : IM_COL32(90, 90, 110, 230))
                         : ctrl ? IM_COL32(140, 220, 140, 230)
                                : IM_COL32(255, 120, 100, 230);
    const bool closed = mShape != CutGesture::Shape::Line;
    ImGui::GetForegroundDrawList()->AddPolyline(points.data(), int(points.size()), colour,
                                                closed ? ImDrawFlags_Closed : ImDrawFlags_None, 2.0f);
}

void GestureTool::drawSettings()
{
    ImGui::PushItemWidth(130);
    float depth = float(mDepth);
    if (ImGui::DragFloat("depth", &depth, 0.1f, 0.0f, 1e4f, depth > 0.0f ? "%.3g" : "through"))
        mDepth = std::max(0.0f, depth);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("How far behind the surface under the first point the cut or mask reaches (0: all the way "
                          "through)");
    ImGui::PopItemWidth();
}

void GestureTool::report(nlohmann::json& out) const
{
    const char* shapes[] = {"lasso", "box", "line"};
    out["gesture"] = {{"shape", shapes[int(mShape)]}, {"masks", mMasks}, {"depth", mDepth}, {"drawing", mCut.active()}};
}

}  // namespace sculpt::ui
