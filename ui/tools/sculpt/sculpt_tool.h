// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file sculpt_tool.h
/// @brief The brush: a left drag on the model is a live stroke of the palette's tool (Ctrl: its
///        inverse, Shift: smooth), one undo step when released. The tool chosen at the start.

#include "core/brushes/brush.h"
#include "ui/sculpting/stroke_controller.h"
#include "ui/tools/tool.h"

namespace sculpt::ui {

class CommandRegistry;
class ToolBox;
class ToolHost;

class SculptTool final : public Tool {
public:
    explicit SculptTool(ToolHost& host) : mHost(host) {}
    /// The brush tools (A, C, I, ...), the radius steps ([ ]) and the mirrors (X Y Z).
    void addCommands(CommandRegistry& registry, ToolBox& box);

    const char* name() const override { return "sculpt"; }
    bool press(const InputEvent& event) override;
    void drag(const InputEvent& event) override;
    void release(const InputEvent& event) override;
    bool holding() const override { return mStroke.active(); }
    /// The stroke ends, kept as one undo step.
    void finish() override;
    bool showsBrush() const override { return true; }

    /// The brush tool a stroke uses now: the stroke's own while one runs, else the palette's
    /// under `mods` (the cursor's colour says which).
    BrushTool toolUnder(int mods) const;

private:
    ToolHost& mHost;
    StrokeController mStroke;
    int mStrokeMods = 0;  // the modifiers the stroke began with
};

}  // namespace sculpt::ui
