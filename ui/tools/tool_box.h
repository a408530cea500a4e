#pragma once
/// @file tool_box.h
/// @brief Every tool the window has, and the one chosen. A tool keeps its settings while another
///        is chosen (the cut's depth, push on contact); choosing one while a gesture is under way
///        waits for it to end.

#include "ui/tools/gesture/gesture_tool.h"
#include "ui/tools/pieces/pieces_tool.h"
#include "ui/tools/sculpt/sculpt_tool.h"

namespace sculpt::ui {

class ToolBox {
public:
    explicit ToolBox(ToolHost& host) : mSculpt(host), mGesture(host), mPieces(host) {}
    ToolBox(const ToolBox&) = delete;
    ToolBox& operator=(const ToolBox&) = delete;

    /// Each tool's commands (its rows choose it).
    void addCommands(CommandRegistry& registry)
    {
        mSculpt.addCommands(registry, *this);
        mGesture.addCommands(registry, *this);
        mPieces.addCommands(registry, *this);
    }

    Tool& current() { return *mCurrent; }
    const Tool& current() const { return *mCurrent; }
    /// Makes `tool` (one of this box's) the current one, unless a gesture is under way.
    void choose(Tool& tool)
    {
        if (mCurrent->holding() || mCurrent == &tool) return;
        mPrevious = mCurrent;
        mCurrent = &tool;
    }
    /// Chooses `tool`, or if it is chosen already, the tool chosen before it (Tab: pieces mode).
    void toggle(Tool& tool) { choose(mCurrent == &tool ? *mPrevious : tool); }
    bool isCurrent(const Tool& tool) const { return mCurrent == &tool; }

    SculptTool& sculpt() { return mSculpt; }
    const SculptTool& sculpt() const { return mSculpt; }
    GestureTool& gesture() { return mGesture; }
    const GestureTool& gesture() const { return mGesture; }
    PiecesTool& pieces() { return mPieces; }
    const PiecesTool& pieces() const { return mPieces; }

private:
    SculptTool mSculpt;
    GestureTool mGesture;
    PiecesTool mPieces;
    Tool* mCurrent = &mSculpt;
    Tool* mPrevious = &mSculpt;
};

}  // namespace sculpt::ui
