#include "ui/commands/commands.h"

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

const CommandRow& commandRow(Command command)
{
    static const std::vector<const CommandRow*> rows = [] {
        std::vector<const CommandRow*> byCommand(kCommandCount, nullptr);
        for (const CommandRow& row : commandTable()) byCommand.at(std::size_t(row.command)) = &row;
        return byCommand;
    }();
    const std::size_t index = std::size_t(command);
    if (index >= rows.size() || !rows[index])
        throw std::logic_error("command " + std::to_string(index) + " has no row in the command table");
    return *rows[index];
}

std::string shortcutText(Command command)
{
    std::string text;
    for (const Chord& b : commandRow(command).chords) {
        if (!text.empty()) text += ", ";
        if (b.mods & kControl) text += "Ctrl+";
        if (b.mods & kShift) text += "Shift+";
        if (b.mods & kAlt) text += "Alt+";
        text += shownKeyName(b.key);
    }
    return text;
}

std::optional<Command> commandForKey(int key, int mods, Scope scope)
{
    const int relevant = mods & (kShift | kControl | kAlt);
    for (const CommandRow& row : commandTable()) {
        if (row.scope != scope) continue;
        for (const Chord& chord : row.chords) {
            if (chord.key == key && chord.mods == relevant) return row.command;
        }
    }
    return std::nullopt;
}

}  // namespace sculpt::ui
