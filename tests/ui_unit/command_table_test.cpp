// SPDX-License-Identifier: Apache-2.0
// The window's commands, as their owners register them: a headless SculptApp's registry has one
// row per command with no key bound twice, and the registry itself refuses a second row for a
// command or a chord bound twice in one scope.

#include "tests/ui_unit/headless_app.h"
#include "ui/commands/command_registry.h"
#include "ui/input/input_event.h"
#include "ui/window/headless_window.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

namespace sculpt::test {
namespace {

using namespace sculpt::ui;

/// A headless window's command registry, as the window registers it.
class CommandTable : public ::testing::Test {
protected:
    TempDir mDir;
    HeadlessWindow mWindow{1280, 800};
    SculptApp mApp{mWindow, headlessOptions(mDir)};
    const CommandRegistry& mCommands = mApp.commands();
};

TEST_F(CommandTable, EveryCommandHasExactlyOneCompleteRow)
{
    std::set<int> seen;
    for (const CommandRow& row : mCommands.rows()) {
        EXPECT_TRUE(seen.insert(int(row.command)).second) << "command " << int(row.command) << " has two rows";
        EXPECT_NE(std::string(row.label), "") << int(row.command);
        EXPECT_NE(std::string(row.help), "") << row.label;
        EXPECT_TRUE(row.run) << row.label;
    }
    EXPECT_EQ(seen.size(), std::size_t(kCommandCount));
    EXPECT_TRUE(mCommands.complete());
    for (int c = 0; c < kCommandCount; ++c) EXPECT_EQ(int(mCommands.row(Command(c)).command), c);
    EXPECT_THROW(mCommands.row(Command(kCommandCount)), std::logic_error);  // never a fallback row
}

TEST_F(CommandTable, NoChordIsBoundTwiceInOneScope)
{
    std::map<std::tuple<Scope, int, int>, std::string> owner;
    for (const CommandRow& row : mCommands.rows()) {
        for (const Chord& chord : row.chords) {
            const auto [it, fresh] = owner.emplace(std::make_tuple(row.scope, chord.key, chord.mods), row.label);
            EXPECT_TRUE(fresh) << keyName(chord.key) << " (mods " << chord.mods << ") is bound to both " << it->second
                               << " and " << row.label;
        }
    }
}

TEST_F(CommandTable, KeysFindTheirCommandAndShowAsTheMenusShowThem)
{
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_Z, kControl), Command::Undo);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_Z, kControl | kShift), Command::Redo);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_ESCAPE, 0), Command::Cancel);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_KP_ENTER, 0), Command::Confirm);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_F12, 0), std::nullopt);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_Z, kAlt | kShift), std::nullopt);  // modifiers match exactly
    EXPECT_EQ(mCommands.shortcutText(Command::Redo), "Ctrl+Shift+Z, Ctrl+Y");
    EXPECT_EQ(mCommands.shortcutText(Command::RadiusSmaller), "[");
    EXPECT_EQ(mCommands.shortcutText(Command::Confirm), "Enter, Numpad Enter");
    EXPECT_EQ(mCommands.shortcutText(Command::Cancel), "Esc");
    EXPECT_EQ(mCommands.shortcutText(Command::SaveStrokes), "");
}

TEST_F(CommandTable, ADialogsKeysAreItsAnswersAndTheViewsKeysStayTheTools)
{
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_S, 0, Scope::Dialog), Command::AnswerSave);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_D, 0, Scope::Dialog), Command::AnswerDiscard);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_R, 0, Scope::Dialog), Command::AnswerRecover);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_ESCAPE, 0, Scope::Dialog), Command::DialogCancel);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_ENTER, 0, Scope::Dialog), Command::DialogConfirm);
    for (int n = 1; n <= 9; ++n)
        EXPECT_EQ(mCommands.forKey(GLFW_KEY_0 + n, 0, Scope::Dialog), Command(int(Command::ChooseGrid1) + n - 1)) << n;
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_S, 0), Command::ToolSmooth);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_S, 0, Scope::Pieces), Command::ScalePiece);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_1, 0), Command::ViewFront);
    EXPECT_EQ(mCommands.forKey(GLFW_KEY_Z, kControl, Scope::Dialog), std::nullopt);  // no undo under a dialog
}

TEST_F(CommandTable, APanelsButtonIsACommandWhoseRuleGreysItOut)
{
    EXPECT_EQ(mApp.commands().whyNot(Command::DeletePiece), "a document keeps at least one piece: this is its last");
    EXPECT_EQ(mApp.commands().whyNot(Command::SoloPiece), "");
    EXPECT_EQ(mApp.commands().whyNot(Command::MovePiece), "Tab first: G, R and S move pieces in pieces mode");
}

CommandRow rowOf(Command command, const char* label, std::vector<Chord> chords, Scope scope = Scope::View)
{
    return {command, label, "what it does", std::move(chords), {}, [] {}, scope};
}

TEST(CommandRegistry, ASecondRowForACommandOrAChordBoundTwiceInAScopeFailsWhenAdded)
{
    CommandRegistry registry;
    registry.add(rowOf(Command::Undo, "Undo", {{GLFW_KEY_Z, kControl}}));
    EXPECT_THROW(registry.add(rowOf(Command::Undo, "Undo again", {})), std::logic_error);
    try {
        registry.add(rowOf(Command::Redo, "Redo", {{GLFW_KEY_Y, kControl}, {GLFW_KEY_Z, kControl}}));
        ADD_FAILURE() << "Ctrl+Z was bound twice";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("is bound to Undo already"), std::string::npos) << e.what();
    }
    EXPECT_EQ(registry.rows().size(), 1u) << "a refused row leaves nothing behind";
    EXPECT_THROW(registry.row(Command::Redo), std::logic_error);
    // The same chord in another scope is another key; a row without an action is refused.
    registry.add(rowOf(Command::AnswerSave, "Save", {{GLFW_KEY_Z, kControl}}, Scope::Dialog));
    EXPECT_EQ(registry.forKey(GLFW_KEY_Z, kControl, Scope::Dialog), Command::AnswerSave);
    EXPECT_EQ(registry.forKey(GLFW_KEY_Z, kControl), Command::Undo);
    CommandRow silent = rowOf(Command::Quit, "Quit", {});
    silent.run = nullptr;
    EXPECT_THROW(registry.add(silent), std::logic_error);
    EXPECT_FALSE(registry.complete());
}

}  // namespace
}  // namespace sculpt::test
