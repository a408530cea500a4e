// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mode.h
/// @brief A panel that owns the view until it is accepted (Enter) or cancelled (Esc): an
///        import's preview, primitives being placed, a morph's frames. The window holds at most
///        one (ModeSlot); what waits for it, the keys, the frame and the report ask the mode, and
///        it draws its own panel and adds its own commands, so a new mode is one class in this
///        folder and a line in ModeSlot::addCommands.
///
/// A mode owns what it puts on screen: dropping it (Esc, or once accepted) takes it off.

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace sculpt {
class IncrementalMesher;
}

namespace sculpt::ui {

class PanelHost;
struct SurfaceHit;

class Mode {
public:
    virtual ~Mode() = default;

    /// Its key in the window's report ("import").
    virtual const char* name() const = 0;
    /// Why edits of the document wait while it is open.
    virtual std::string waitNotice() const = 0;
    /// What the status bar says when it opens (and stops saying when it closes).
    virtual std::string hint() const = 0;

    /// Once per frame: brings its previews up to date. @return true if a new one went on screen.
    virtual bool sync(double now) = 0;
    /// The mesh to show instead of the document's (a morph frame), or nullptr.
    virtual const IncrementalMesher* shownMesher() const { return nullptr; }
    virtual bool hidesDocument() const { return false; }
    virtual bool showsBrush() const { return true; }
    /// A replay's wait event waits while this is true (a morph playing).
    virtual bool holdsReplay() const { return false; }

    /// PageUp (+1) or PageDown (-1).
    virtual void step(int /*direction*/) {}
    /// A left press on the surface: true if the mode takes it, and the drag that follows.
    virtual bool press(const SurfaceHit& /*hit*/) { return false; }
    virtual void drag(const SurfaceHit& /*hit*/) {}

    /// Enter: hands its result to the host (a job, an edit). @return true once the mode is done
    /// (false: it waits, for instance for the answer to "save changes?").
    virtual bool accept(PanelHost& host) = 0;

    virtual void drawPanel(PanelHost& host) = 0;
    virtual nlohmann::json report() = 0;
};

}  // namespace sculpt::ui
