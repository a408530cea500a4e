// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file interrupt_cleanup.h
/// @brief Files that exist only while being written (AtomicFile's temporaries), removed when an
///        interruption ends the program: Ctrl-C (SIGINT), a scheduler's time limit or `kill`
///        (SIGTERM), a closed terminal (SIGHUP).
///
/// The handler works at once, whatever the program is doing: it removes the registered files,
/// says so on stderr and exits with 128 + the signal's number (130, 143, 129), as shells and
/// schedulers expect. Finished files stay: every one was written whole and renamed in one step.

#include <filesystem>

namespace sculpt {

/// Registers `path` for removal on an interruption; returns its ticket for forgetTemporary, or
/// -1 if the path is too long or too many are registered (then it is not removed).
int registerTemporary(const std::filesystem::path& path);
/// The file at `ticket` is gone or no longer temporary (no-op for -1).
void forgetTemporary(int ticket);

/// Installs the handlers for SIGINT, SIGTERM and SIGHUP. A signal ignored when the program
/// started stays ignored (`nohup`, a shell's background job). `program` prefixes the message and
/// must outlive the program.
void exitCleanlyOnInterrupt(const char* program);

}  // namespace sculpt
