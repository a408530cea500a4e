// The window's command table, read without a window: one row per command, no key bound twice,
// and the keys shown as menus and Help show them.

#include "ui/commands/commands.h"
#include "ui/input/input_event.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>

using namespace sculpt::ui;

TEST(CommandTable, EveryCommandHasExactlyOneCompleteRow)
{
    std::set<int> seen;
    for (const CommandRow& row : commandTable()) {
        EXPECT_TRUE(seen.insert(int(row.command)).second) << "command " << int(row.command) << " has two rows";
        EXPECT_NE(std::string(row.label), "") << int(row.command);
        EXPECT_NE(std::string(row.help), "") << row.label;
        EXPECT_NE(row.run, nullptr) << row.label;
    }
    EXPECT_EQ(seen.size(), std::size_t(kCommandCount));
    for (int c = 0; c < kCommandCount; ++c) EXPECT_EQ(int(commandRow(Command(c)).command), c);
    EXPECT_THROW(commandRow(Command(kCommandCount)), std::logic_error);  // never a fallback row
}

TEST(CommandTable, NoChordIsBoundTwiceInOneScope)
{
    std::map<std::tuple<Scope, int, int>, std::string> owner;
    for (const CommandRow& row : commandTable()) {
        for (const Chord& chord : row.chords) {
            const auto [it, fresh] = owner.emplace(std::make_tuple(row.scope, chord.key, chord.mods), row.label);
            EXPECT_TRUE(fresh) << keyName(chord.key) << " (mods " << chord.mods << ") is bound to both " << it->second
                               << " and " << row.label;
        }
    }
}

TEST(CommandTable, KeysFindTheirCommandAndShowAsTheMenusShowThem)
{
    EXPECT_EQ(commandForKey(GLFW_KEY_Z, kControl), Command::Undo);
    EXPECT_EQ(commandForKey(GLFW_KEY_Z, kControl | kShift), Command::Redo);
    EXPECT_EQ(commandForKey(GLFW_KEY_ESCAPE, 0), Command::Cancel);
    EXPECT_EQ(commandForKey(GLFW_KEY_KP_ENTER, 0), Command::Confirm);
    EXPECT_EQ(commandForKey(GLFW_KEY_F12, 0), std::nullopt);
    EXPECT_EQ(commandForKey(GLFW_KEY_Z, kAlt | kShift), std::nullopt);  // modifiers match exactly
    EXPECT_EQ(shortcutText(Command::Redo), "Ctrl+Shift+Z, Ctrl+Y");
    EXPECT_EQ(shortcutText(Command::RadiusSmaller), "[");
    EXPECT_EQ(shortcutText(Command::Confirm), "Enter, Numpad Enter");
    EXPECT_EQ(shortcutText(Command::Cancel), "Esc");
    EXPECT_EQ(shortcutText(Command::SaveStrokes), "");
}

TEST(CommandTable, ADialogsKeysAreItsAnswersAndTheViewsKeysStayTheTools)
{
    EXPECT_EQ(commandForKey(GLFW_KEY_S, 0, Scope::Dialog), Command::AnswerSave);
    EXPECT_EQ(commandForKey(GLFW_KEY_D, 0, Scope::Dialog), Command::AnswerDiscard);
    EXPECT_EQ(commandForKey(GLFW_KEY_R, 0, Scope::Dialog), Command::AnswerRecover);
    EXPECT_EQ(commandForKey(GLFW_KEY_ESCAPE, 0, Scope::Dialog), Command::DialogCancel);
    EXPECT_EQ(commandForKey(GLFW_KEY_ENTER, 0, Scope::Dialog), Command::DialogConfirm);
    for (int n = 1; n <= 9; ++n)
        EXPECT_EQ(commandForKey(GLFW_KEY_0 + n, 0, Scope::Dialog), Command(int(Command::ChooseGrid1) + n - 1)) << n;
    EXPECT_EQ(commandForKey(GLFW_KEY_S, 0), Command::ToolSmooth);
    EXPECT_EQ(commandForKey(GLFW_KEY_1, 0), Command::ViewFront);
    EXPECT_EQ(commandForKey(GLFW_KEY_Z, kControl, Scope::Dialog), std::nullopt);  // no undo under a dialog
}
