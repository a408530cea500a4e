// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file command_registry.h
/// @brief The window's commands, each added by its owner (F3D's addCommand): a second row for a
///        command, or a chord bound twice in one scope, fails when it is added, so a clash is
///        found at start-up (and in a test), never as a key that silently does the other thing.

#include "ui/commands/commands.h"

#include <optional>
#include <string>
#include <vector>

namespace sculpt::ui {

class CommandRegistry {
public:
    /// Adds `row`. @throws std::logic_error if its command has a row already, a chord of it is
    ///         bound in its scope already, or it has no label, help or action.
    void add(CommandRow row);

    /// The rows in the order they were added.
    const std::vector<CommandRow>& rows() const { return mRows; }
    /// The row of `command`. @throws std::logic_error if none was added (a programming error).
    const CommandRow& row(Command command) const;
    /// True once every Command has a row.
    bool complete() const { return mRows.size() == std::size_t(kCommandCount); }
    /// Why `command` cannot run now, or "" when it can.
    std::string whyNot(Command command) const;
    /// The command bound to this key and modifiers in `scope`, if any.
    std::optional<Command> forKey(int key, int mods, Scope scope = Scope::View) const;
    /// "Ctrl+Shift+Z, Ctrl+Y" for a command; "" if it has no key.
    std::string shortcutText(Command command) const;

private:
    std::vector<CommandRow> mRows;
    std::vector<int> mIndex = std::vector<int>(std::size_t(kCommandCount), -1);  // row of each command
};

}  // namespace sculpt::ui
