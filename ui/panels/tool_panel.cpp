// SPDX-License-Identifier: Apache-2.0
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

namespace sculpt::ui {

namespace {

struct ToolButton {
    BrushTool tool;
    Command command;
};

constexpr ToolButton kTools[] = {
    {BrushTool::Add, Command::ToolAdd},         {BrushTool::Carve, Command::ToolCarve},
    {BrushTool::Inflate, Command::ToolInflate}, {BrushTool::Deflate, Command::ToolDeflate},
    {BrushTool::Smooth, Command::ToolSmooth},   {BrushTool::Flatten, Command::ToolFlatten},
    {BrushTool::Grab, Command::ToolGrab},       {BrushTool::Pinch, Command::ToolPinch},
    {BrushTool::Follow, Command::ToolFollow},   {BrushTool::Primitive, Command::ToolPrimitive},
    {BrushTool::Mask, Command::ToolMask},
};

constexpr const char* kFalloffs[] = {"smooth", "sphere", "sharp", "constant"};

void toolPalette(PanelHost& host)
{
    BrushOptions& b = host.brush();
    ToolBox& tools = host.tools();
    for (int i = 0; i < int(std::size(kTools)); ++i) {
        const bool current = b.tool == kTools[i].tool && tools.isCurrent(tools.get<SculptTool>());
        if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        if (ImGui::Button(host.commands().row(kTools[i].command).label, ImVec2(68, 0))) host.execute(kTools[i].command);
        if (current) ImGui::PopStyleColor();
        commandTooltip(host, kTools[i].command);
        if (i % 3 != 2 && i + 1 < int(std::size(kTools))) ImGui::SameLine();
    }
    struct Gesture {
        CutGesture::Shape shape;
        bool masks;
        Command command;
    };
    constexpr Gesture kGestures[] = {{CutGesture::Shape::Lasso, false, Command::ToolLassoCut},
                                     {CutGesture::Shape::Box, false, Command::ToolBoxCut},
                                     {CutGesture::Shape::Line, false, Command::ToolLineCut},
                                     {CutGesture::Shape::Lasso, true, Command::ToolLassoMask},
                                     {CutGesture::Shape::Box, true, Command::ToolBoxMask}};
    for (int i = 0; i < int(std::size(kGestures)); ++i) {
        const Gesture& g = kGestures[i];
        const bool current = tools.isCurrent(tools.get<GestureTool>()) && tools.get<GestureTool>().shape() == g.shape &&
                             tools.get<GestureTool>().masks() == g.masks;
        if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        // Three cuts to a row, the two masks (longer names) on one of their own.
        if (ImGui::Button(host.commands().row(g.command).label, ImVec2(g.masks ? 106 : 68, 0))) host.execute(g.command);
        if (current) ImGui::PopStyleColor();
        commandTooltip(host, g.command);
        if (i != 2 && i + 1 < int(std::size(kGestures))) ImGui::SameLine();
    }
    tools.current().drawSettings();
}

}  // namespace

void drawToolPanel(PanelHost& host)
{
    ImGui::SetNextWindowPos(ImVec2(8, 28), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(236, 0), ImGuiCond_Always);
    ImGui::Begin("Brush", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    toolPalette(host);
    BrushOptions& b = host.brush();
    ImGui::PushItemWidth(130);
    float radius = float(b.radius), strength = float(b.strength), spacing = float(b.spacing);
    const float voxel = float(host.document().session().field().voxelSize());
    if (ImGui::DragFloat("radius", &radius, 0.02f * radius, 0.5f * voxel, 400.f * voxel, "%.3g")) b.radius = radius;
    commandTooltip(host, Command::RadiusDrag);
    if (ImGui::SliderFloat("strength", &strength, 0.01f, 1.f, "%.2f")) b.strength = strength;
    commandTooltip(host, Command::StrengthDrag);
    int falloff = int(b.falloff);
    if (ImGui::Combo("falloff", &falloff, kFalloffs, int(std::size(kFalloffs)))) b.falloff = Falloff(falloff);
    if (ImGui::SliderFloat("spacing", &spacing, 0.05f, 1.f, "%.2f r")) b.spacing = spacing;
    ImGui::PopItemWidth();
    ImGui::Text("mirror");
    ImGui::SameLine();
    ImGui::Checkbox("X", &b.symmetry.x);
    commandTooltip(host, Command::SymmetryX);
    ImGui::SameLine();
    ImGui::Checkbox("Y", &b.symmetry.y);
    commandTooltip(host, Command::SymmetryY);
    ImGui::SameLine();
    ImGui::Checkbox("Z", &b.symmetry.z);
    commandTooltip(host, Command::SymmetryZ);
    ImGui::Checkbox("pressure from speed", &b.pressureFromSpeed);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A mouse has no pressure: faster strokes press lighter");
    if (b.tool == BrushTool::Smooth) ImGui::Checkbox("keep volume", &b.keepVolume);
    if (b.tool == BrushTool::Follow) {
        if (b.target.shape) ImGui::Text("target: %s", b.target.path.filename().string().c_str());
        else warningText("no target: Ctrl+T loads one", 200.f);
    }
    ImGui::TextDisabled("Ctrl inverts, Shift smooths");
    ImGui::End();
}

}  // namespace sculpt::ui
