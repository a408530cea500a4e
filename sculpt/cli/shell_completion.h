// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file shell_completion.h
/// @brief Shell completion scripts made from the program's own command tree, so they always
///        know every command, option and choice the build has (`sculpt --completion bash`; the
///        install puts one for bash, zsh and fish where each shell looks).

#include <string>

namespace CLI {
class App;
}

namespace sculpt::cli {

/// The completion script of `app` for `shell` ("bash", "zsh" or "fish").
/// @throws InputError for another shell.
std::string completionScript(const CLI::App& app, const std::string& shell);

}  // namespace sculpt::cli
