// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file tool.h
/// @brief What a left press on the view does until another tool is chosen: sculpt with the brush,
///        cut or mask along a gesture, pick and move pieces. Beside a Mode (which owns the view
///        until accepted or cancelled), a tool stays chosen; the window holds them in a ToolBox
///        and routes the pointer and keys to the current one, so a new tool is one folder here
///        and a line in ToolBox.
///
/// A tool *holds* the input while its gesture is under way (a stroke, a cut being drawn, a piece
/// following the pointer): moves, releases and keys go to it, and the camera keeps still.

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>

namespace sculpt::ui {

struct InputEvent;
enum class Scope;

class Tool {
public:
    virtual ~Tool() = default;

    /// Its name in the window's report ("sculpt", "gesture", "pieces").
    virtual const char* name() const = 0;
    /// A press of a mouse button on the view (a left one without Alt, or any while holding).
    /// @return true if the tool took it (its gesture began or ended); false: the view navigates.
    virtual bool press(const InputEvent& event) = 0;
    /// The pointer moved while holding.
    virtual void drag(const InputEvent& /*event*/) {}
    /// A button released while holding.
    virtual void release(const InputEvent& /*event*/) {}
    /// A key pressed while holding. @return true if taken (else it does nothing: keys wait).
    virtual bool key(const InputEvent& /*event*/) { return false; }
    /// Its gesture is under way.
    virtual bool holding() const = 0;
    /// Ends the gesture under way (the window closes, an internal error): what it made so far is
    /// kept (a stroke) or dropped (a cut not yet landed, a piece not yet placed).
    virtual void finish() {}

    /// Why an edit of the document must wait for its gesture, or "".
    virtual std::string waitReason() const { return {}; }
    /// Its keys' scope, tried before the view's (Scope::Pieces), if it has one.
    virtual std::optional<Scope> keyScope() const { return std::nullopt; }
    /// A press on the surface goes to the open mode first (placing a primitive), else to the tool.
    virtual bool yieldsToMode() const { return true; }
    /// The brush cursor shows under the pointer (and the surface there is picked while holding).
    virtual bool showsBrush() const { return false; }

    /// Its drawing over the view (a cut's outline), each frame.
    virtual void drawOverlay() const {}
    /// Its settings in the Brush panel, under the palette.
    virtual void drawSettings() {}
    /// Its state in the window's report.
    virtual void report(nlohmann::json& /*out*/) const {}
};

}  // namespace sculpt::ui
