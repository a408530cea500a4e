// SPDX-License-Identifier: Apache-2.0
// Shell completion made from the command tree: bash completes what --help lists; the zsh and fish
// scripts parse in their shells.

#include "tests/support/run_sculpt.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

namespace sculpt {
namespace {

using test::runCommand;
using test::runSculpt;
using test::TempDir;

/// What bash's completion offers for the words `line` ending with `current`.
std::set<std::string> bashCompletes(const TempDir& dir, const std::string& line, const std::string& current)
{
    const auto r = runCommand("bash -c 'source sculpt.bash; COMP_WORDS=(sculpt " + line + " \"" + current +
                                  "\"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _sculpt; printf \"%s\\n\" "
                                  "\"${COMPREPLY[@]}\"'",
                              dir.path().string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::set<std::string> words;
    std::istringstream lines(r.out);
    for (std::string word; std::getline(lines, word);)
        if (!word.empty()) words.insert(word);
    return words;
}

TEST(Completion, BashOffersEveryOptionEachCommandsHelpLists)
{
    TempDir dir;
    const auto script = runSculpt("--completion bash", dir.path());
    ASSERT_EQ(script.exitCode, 0);
    std::ofstream(dir / "sculpt.bash") << script.out;
    const std::set<std::string> commands = bashCompletes(dir, "", "");
    for (const std::string& command : test::sculptCommands()) {
        EXPECT_TRUE(commands.count(command)) << command;
        const std::set<std::string> offered = bashCompletes(dir, command, "-");
        const std::string help = runSculpt(command + " --help", dir.path()).out;
        const std::regex option("(^|[ ,])(--[a-z][a-z-]*)");
        std::size_t listed = 0;
        for (auto it = std::sregex_iterator(help.begin(), help.end(), option); it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[2];
            if (help.find("  " + name) == std::string::npos && help.find("," + name) == std::string::npos)
                continue;  // named in a description, not an option of this command
            EXPECT_TRUE(offered.count(name)) << command << " " << name;
            ++listed;
        }
        EXPECT_GT(listed, 3u) << command;
    }
    // A value from a fixed set completes to its choices.
    EXPECT_EQ(bashCompletes(dir, "hollow in.vdb --side", ""), (std::set<std::string>{"inside", "medial", "outside"}));
    EXPECT_EQ(bashCompletes(dir, "new --shape", "t"), std::set<std::string>{"torus"});
}

TEST(Completion, ZshAndFishScriptsParse)
{
    TempDir dir;
    for (const char* shell : {"zsh", "fish"}) {
        if (runCommand(std::string("command -v ") + shell, dir.path().string()).exitCode != 0) {
            std::cout << shell << " is not installed: its script is not parsed here\n";
            continue;
        }
        const auto script = runSculpt(std::string("--completion ") + shell, dir.path());
        ASSERT_EQ(script.exitCode, 0);
        std::ofstream(dir / "script") << script.out;
        const auto r = runCommand(std::string(shell) + " -n script", dir.path().string());
        EXPECT_EQ(r.exitCode, 0) << shell << ": " << r.err;
    }
    EXPECT_EQ(runSculpt("--completion tcsh", dir.path()).exitCode, 2);
}

}  // namespace
}  // namespace sculpt
