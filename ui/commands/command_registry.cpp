// SPDX-License-Identifier: Apache-2.0
#include "ui/commands/command_registry.h"

#include "ui/input/input_event.h"

#include <stdexcept>
#include <utility>

namespace sculpt::ui {

namespace {

/// A key as menus and Help show it: "[" rather than the recordings' "LeftBracket".
std::string shownKeyName(int key)
{
    static const std::vector<std::pair<std::string, std::string>> shown = {{"LeftBracket", "["},
                                                                           {"RightBracket", "]"},
                                                                           {"KPDecimal", "Numpad ."},
                                                                           {"KPEnter", "Numpad Enter"},
                                                                           {"Escape", "Esc"}};
    const std::string name = keyName(key);
    for (const auto& [recorded, display] : shown) {
        if (name == recorded) return display;
    }
    return name;
}

}  // namespace

void CommandRegistry::add(CommandRow row)
{
    const std::size_t index = std::size_t(row.command);
    const std::string name = row.label ? row.label : "command " + std::to_string(index);
    if (index >= mIndex.size()) throw std::logic_error(name + ": not a command");
    if (mIndex[index] >= 0) throw std::logic_error(name + ": the command has a row already");
    if (!row.label || !*row.label || !row.help || !*row.help || !row.run)
        throw std::logic_error(name + ": a command needs a label, a help text and an action");
    for (const Chord& chord : row.chords) {
        if (const std::optional<Command> bound = forKey(chord.key, chord.mods, row.scope))
            throw std::logic_error(name + ": " + keyName(chord.key) + " (modifiers " + std::to_string(chord.mods) +
                                   ") is bound to " + this->row(*bound).label + " already");
    }
    mIndex[index] = int(mRows.size());
    mRows.push_back(std::move(row));
}

const CommandRow& CommandRegistry::row(Command command) const
{
    const std::size_t index = std::size_t(command);
    if (index >= mIndex.size() || mIndex[index] < 0)
        throw std::logic_error("command " + std::to_string(index) + " has no row in the registry");
    return mRows[std::size_t(mIndex[index])];
}

std::string CommandRegistry::whyNot(Command command) const
{
    const CommandRow& found = row(command);
    return found.blocked ? found.blocked() : std::string();
}

std::string CommandRegistry::shortcutText(Command command) const
{
    std::string text;
    for (const Chord& b : row(command).chords) {
        if (!text.empty()) text += ", ";
        if (b.mods & kControl) text += "Ctrl+";
        if (b.mods & kShift) text += "Shift+";
        if (b.mods & kAlt) text += "Alt+";
        text += shownKeyName(b.key);
    }
    return text;
}

std::optional<Command> CommandRegistry::forKey(int key, int mods, Scope scope) const
{
    const int relevant = mods & (kShift | kControl | kAlt);
    for (const CommandRow& row : mRows) {
        if (row.scope != scope) continue;
        for (const Chord& chord : row.chords) {
            if (chord.key == key && chord.mods == relevant) return row.command;
        }
    }
    return std::nullopt;
}

}  // namespace sculpt::ui
