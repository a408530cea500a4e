// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file run_options.h
/// @brief The options every command that computes takes alike, for scripts and batch jobs:
///        `--threads N`, `--quiet` and `--json`.

#include <string>

namespace CLI {
class App;
}

namespace sculpt::cli {

struct RunOptions {
    int threads = 0;  ///< 0: every core
    bool quiet = false;
    bool json = false;
};

/// Adds the three options to `cmd` (`jsonHelp` describes its report's keys, if not the schema
/// alone); once its options are parsed, the thread limit holds for the rest of the run and
/// --quiet hides the progress bar.
void addRunOptions(CLI::App& cmd, RunOptions& options, const std::string& jsonHelp = "");

}  // namespace sculpt::cli
