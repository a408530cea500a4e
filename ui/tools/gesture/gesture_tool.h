// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file gesture_tool.h
/// @brief Cut and mask gestures: a box, lasso or line drawn on the screen sweeps a prism along the
///        view that cuts through the model (Ctrl: fills it with clay) or masks the clay it covers
///        (Ctrl: unmasks), all the way or a slab from the surface under its first point, mirrored
///        by the brush's symmetry; a job that lands as one undo step and in the stroke log.

#include "ui/tools/gesture/cut_gesture.h"
#include "ui/tools/tool.h"

namespace sculpt::ui {

class CommandRegistry;
class ToolBox;
class ToolHost;

class GestureTool final : public Tool {
public:
    explicit GestureTool(ToolHost& host) : mHost(host) {}
    /// The cut tools (J, Shift+J, Alt+J) and the mask gestures (Shift+B, Alt+B).
    void addCommands(CommandRegistry& registry, ToolBox& box);

    /// The gesture a press draws from now on, and whether it masks instead of cutting.
    void choose(CutGesture::Shape shape, bool masks);
    CutGesture::Shape shape() const { return mShape; }
    bool masks() const { return mMasks; }

    const char* name() const override { return "gesture"; }
    bool press(const InputEvent& event) override;
    void drag(const InputEvent& event) override;
    /// The left button's release cuts (or masks) with the prism drawn.
    void release(const InputEvent& event) override;
    bool holding() const override { return mCut.active(); }
    /// Esc while drawing drops the gesture: nothing is cut.
    bool key(const InputEvent& event) override;
    /// Drops the gesture drawn so far: nothing is cut.
    void finish() override { mCut.clear(); }
    void drawOverlay() const override;
    /// How deep the prism reaches behind the surface under the first point (0: all the way).
    void drawSettings() override;
    void report(nlohmann::json& out) const override;

private:
    void land();

    ToolHost& mHost;
    CutGesture::Shape mShape = CutGesture::Shape::Lasso;
    bool mMasks = false;
    CutGesture mCut;
    double mDepth = 0.0;
    int mMods = 0;       // the modifiers held when the gesture began (Ctrl: fill, unmask)
    double mNear = 0.0;  // the depth of the surface under its first point (the view's focus off it)
};

}  // namespace sculpt::ui
