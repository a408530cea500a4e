// SPDX-License-Identifier: Apache-2.0
// The Slices view's labels, drawn over its three views: each view's name and plane, the
// patient's directions at its edges, and the window and level.

#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

#include <cstdio>

namespace sculpt::ui {

namespace {

/// The patient's directions at a view's left, right, top and bottom edges (SliceViews' axes).
struct EdgeLetters {
    const char *left, *right, *top, *bottom;
};
constexpr EdgeLetters kEdges[] = {{"A", "P", "S", "I"}, {"R", "L", "S", "I"}, {"R", "L", "A", "P"}};
constexpr const char* kAxisLetters = "xyz";

}  // namespace

void drawSliceLabels(PanelHost& host)
{
    const SliceViews& slices = host.view().slices();
    if (!slices.shown() || !slices.hasScan()) return;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImU32 text = IM_COL32(235, 235, 235, 255), faint = IM_COL32(170, 200, 170, 255);
    for (int a = 0; a < 3; ++a) {
        const PixelRect& r = slices.rect(SliceAxis(a));
        char label[64];
        std::snprintf(label, sizeof label, "%s  %c %.1f mm", kSliceNames[a], kAxisLetters[a], slices.cursor()[a]);
        draw->AddText({float(r.x + 4), float(r.y + 2)}, text, label);
        const EdgeLetters& e = kEdges[a];
        const float mx = float(r.x + 0.5 * r.width), my = float(r.y + 0.5 * r.height);
        draw->AddText({float(r.x + 3), my - 7}, faint, e.left);
        draw->AddText({float(r.x + r.width - 11), my - 7}, faint, e.right);
        draw->AddText({mx - 4, float(r.y + 16)}, faint, e.top);
        draw->AddText({mx - 4, float(r.y + r.height - 16)}, faint, e.bottom);
    }
    const PixelRect& first = slices.rect(SliceAxis::Axial);
    char wl[64];
    std::snprintf(wl, sizeof wl, "W %.0f  L %.0f  (right drag)", slices.window(), slices.level());
    draw->AddText({float(first.x + 4), float(first.y + first.height - 16)}, text, wl);
}

}  // namespace sculpt::ui
