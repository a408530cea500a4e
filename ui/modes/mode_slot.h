// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mode_slot.h
/// @brief The one mode open at a time: opened in place of the one before (its hint in the status
///        bar), accepted (Enter: it hands its result over and closes; an error keeps it open) or
///        closed (Esc); and the commands of the modes, each mode adding its own.

#include "ui/modes/mode.h"

#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <string>

namespace sculpt::ui {

class CommandRegistry;
class PanelHost;

class ModeSlot {
public:
    explicit ModeSlot(PanelHost& host) : mHost(host) {}

    /// The open mode, or nullptr.
    Mode* get() const { return mMode.get(); }
    /// The open mode if it is an M (a MorphMode, an ImportMode...), else nullptr.
    template <typename M>
    M* as() const
    {
        return dynamic_cast<M*>(mMode.get());
    }
    PanelHost& host() { return mHost; }

    /// Opens `mode` in place of the one open; the status bar shows its hint.
    void open(std::unique_ptr<Mode> mode);
    /// Drops the open mode and what it shows; the document stays as it was.
    void close();
    /// The open mode hands its result over and closes (an error keeps it open).
    void accept();
    /// Why edits of the document wait for the open mode, or "".
    std::string waitNotice() const { return mMode ? mMode->waitNotice() : std::string(); }
    void drawPanel();

    /// Apply, Cancel and the steps, then each mode's own commands.
    void addCommands(CommandRegistry& commands);
    /// The open mode's name ("mode") and its own report under that name.
    void report(nlohmann::json& out) const;

private:
    PanelHost& mHost;
    std::unique_ptr<Mode> mMode;
};

}  // namespace sculpt::ui
