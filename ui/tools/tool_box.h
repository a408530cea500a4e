// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file tool_box.h
/// @brief Every tool the window has, and the one chosen. A tool keeps its settings while another
///        is chosen (the cut's depth, push on contact); choosing one while a gesture is under way
///        waits for it to end. A new tool is its folder and one line here: its type in `Tools`.

#include "ui/tools/gesture/gesture_tool.h"
#include "ui/tools/pieces/pieces_tool.h"
#include "ui/tools/sculpt/sculpt_tool.h"

#include <tuple>

namespace sculpt::ui {

class ToolBox {
public:
    /// The tools, the first chosen at the start.
    using Tools = std::tuple<SculptTool, GestureTool, PiecesTool>;

    explicit ToolBox(ToolHost& host) : ToolBox(host, std::make_index_sequence<std::tuple_size_v<Tools>>()) {}
    ToolBox(const ToolBox&) = delete;
    ToolBox& operator=(const ToolBox&) = delete;

    /// Each tool's commands (its rows choose it).
    void addCommands(CommandRegistry& registry)
    {
        std::apply([&](auto&... tool) { (tool.addCommands(registry, *this), ...); }, mTools);
    }

    /// The tool of type T.
    template <typename T>
    T& get()
    {
        return std::get<T>(mTools);
    }
    template <typename T>
    const T& get() const
    {
        return std::get<T>(mTools);
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

private:
    template <std::size_t... I>
    ToolBox(ToolHost& host, std::index_sequence<I...>) : mTools(((void)I, host)...)
    {}

    Tools mTools;
    Tool* mCurrent = &std::get<0>(mTools);
    Tool* mPrevious = mCurrent;
};

}  // namespace sculpt::ui
