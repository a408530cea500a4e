// SPDX-License-Identifier: Apache-2.0
// PrimitivesMode's panel: the primitives' list, the selected one's skeleton and kernel, the
// scene's iso-value and operation; Bake, Load and Save.

#include "ui/modes/primitives_mode.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace sculpt::ui {

namespace {

constexpr float kPanelWidth = 340.f;
constexpr const char* kSkeletons[] = {"point", "segment", "triangle", "box"};
constexpr const char* kKernels[] = {"blobby molecule", "metaball", "soft object"};
constexpr const char* kOperations[] = {"union", "difference", "intersection", "replace"};

std::string labelOf(const Primitive& p, int index)
{
    return (p.name.empty() ? std::string(kSkeletons[int(p.skeleton.type)]) + " " + std::to_string(index + 1) : p.name) +
           "##" + std::to_string(index);
}

bool vec3Field(const char* label, openvdb::Vec3d& v)
{
    float f[3] = {float(v.x()), float(v.y()), float(v.z())};
    ImGui::SetNextItemWidth(190.f);
    if (!ImGui::DragFloat3(label, f, 0.05f, 0.f, 0.f, "%.3g")) return false;
    v = openvdb::Vec3d(f[0], f[1], f[2]);
    return true;
}

void addButtons(PanelHost& host, PrimitiveDraft& draft)
{
    ImGui::TextUnformatted("add at the pointer:");
    for (int t = 0; t < 4; ++t) {
        if (t) ImGui::SameLine();
        if (ImGui::Button(kSkeletons[t])) PrimitivesMode::addAtPointer(host, draft, SkeletonType(t));
    }
}

void primitiveList(PrimitiveDraft& draft)
{
    ImGui::BeginChild("list", ImVec2(0.f, 90.f), true);
    for (int i = 0; i < int(draft.primitives.size()); ++i) {
        if (ImGui::Selectable(labelOf(draft.primitives[size_t(i)], i).c_str(), draft.selected == i)) draft.selected = i;
    }
    ImGui::EndChild();
}

void skeletonFields(Skeleton& s)
{
    switch (s.type) {
    case SkeletonType::Point: vec3Field("position", s.points[0]); break;
    case SkeletonType::Segment:
        vec3Field("from", s.points[0]);
        vec3Field("to", s.points[1]);
        break;
    case SkeletonType::Triangle:
        vec3Field("a", s.points[0]);
        vec3Field("b", s.points[1]);
        vec3Field("c", s.points[2]);
        break;
    case SkeletonType::Box:
        vec3Field("centre", s.points[0]);
        vec3Field("half extents", s.halfExtents);
        break;
    }
}

/// The primitives the selected one blends with (a blending graph once any is ticked).
void neighbourFields(PrimitiveDraft& draft)
{
    if (draft.primitives.size() < 2) return;
    ImGui::PushTextWrapPos(kPanelWidth - 10.f);
    ImGui::TextDisabled("blends with (none ticked anywhere: all blend)");
    ImGui::PopTextWrapPos();
    Primitive& p = draft.primitives[size_t(draft.selected)];
    for (int j = 0; j < int(draft.primitives.size()); ++j) {
        if (j == draft.selected) continue;
        const auto found = std::find(p.neighbours.begin(), p.neighbours.end(), j);
        bool on = found != p.neighbours.end();
        if (!ImGui::Checkbox(labelOf(draft.primitives[size_t(j)], j).c_str(), &on)) continue;
        if (on) p.neighbours.push_back(j);
        else p.neighbours.erase(found);
    }
}

void selectedFields(PanelHost& host, PrimitiveDraft& draft)
{
    if (draft.selected < 0) return;
    Primitive& p = draft.primitives[size_t(draft.selected)];
    skeletonFields(p.skeleton);
    int kernel = int(p.kernel.type);
    ImGui::SetNextItemWidth(190.f);
    if (ImGui::Combo("kernel", &kernel, kKernels, int(std::size(kKernels)))) p.kernel.type = KernelType(kernel);
    float radius = float(p.kernel.radius), strength = float(p.kernel.strength);
    ImGui::SetNextItemWidth(190.f);
    if (ImGui::DragFloat("reach", &radius, 0.02f * radius, 1e-3f, 1e6f, "%.3g")) p.kernel.radius = radius;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The kernel's radius of influence, world units");
    ImGui::SetNextItemWidth(190.f);
    if (ImGui::SliderFloat("strength", &strength, 0.05f, 2.f, "%.2f")) p.kernel.strength = strength;
    neighbourFields(draft);
    if (ImGui::Button("Remove (Delete)")) host.execute(Command::RemovePrimitive);
}

}  // namespace

void PrimitivesMode::drawPanel(PanelHost& host)
{
    PrimitiveDraft& draft = mDraft;
    beginSidePanel("Primitives", kPanelWidth);
    addButtons(host, draft);
    primitiveList(draft);
    selectedFields(host, draft);
    ImGui::Separator();
    float iso = float(draft.iso);
    ImGui::SetNextItemWidth(120.f);
    if (ImGui::SliderFloat("iso-value", &iso, 0.05f, 0.95f, "%.2f")) draft.iso = iso;
    int operation = int(draft.operation);
    ImGui::SetNextItemWidth(120.f);
    if (ImGui::Combo("into the model", &operation, kOperations, int(std::size(kOperations))))
        draft.operation = CsgOperation(operation);
    if (!draft.problem().empty()) warningText(draft.problem(), kPanelWidth - 20.f);
    ImGui::PushTextWrapPos(kPanelWidth - 10.f);
    ImGui::TextDisabled("click or drag on the surface moves the selected one");
    ImGui::PopTextWrapPos();
    if (ImGui::Button("Bake (Enter)")) host.execute(Command::Confirm);
    commandTooltip(host, Command::BakePrimitives);
    ImGui::SameLine();
    if (ImGui::Button("Save...")) host.execute(Command::SaveScene);
    commandTooltip(host, Command::SaveScene);
    ImGui::SameLine();
    if (ImGui::Button("Load...")) host.execute(Command::LoadScene);
    commandTooltip(host, Command::LoadScene);
    ImGui::SameLine();
    if (ImGui::Button("Close (Esc)")) host.execute(Command::Cancel);
    ImGui::End();
}

}  // namespace sculpt::ui
