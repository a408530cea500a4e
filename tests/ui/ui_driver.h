// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file ui_driver.h
/// @brief Drives the real sculpt-ui under Xvfb for tests: builds an event recording, replays it
///        (--play), and reads back the reports and screenshots it wrote.

#include "tests/support/run_sculpt.h"
#include "tests/support/ui_events.h"

#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>

class vtkImageData;

namespace sculpt::test {

/// `xvfb-run -a sculpt-ui ARGS` in `workDir` (a 1280x800 screen).
CommandResult runUi(const std::string& args, const std::string& workDir);
/// The command line of that, for running it in the background.
std::string uiCommand(const std::string& args);

/// sculpt-ui started in the background (uiCommand) in a process group of its own: the test keeps
/// that group's id, and the destructor kills what is left of it, so an ASSERT that returns early
/// leaves no window or X server running. Nothing is ever looked up by name.
class BackgroundUi {
public:
    BackgroundUi(const std::string& args, const std::filesystem::path& workDir);
    ~BackgroundUi();
    BackgroundUi(const BackgroundUi&) = delete;
    BackgroundUi& operator=(const BackgroundUi&) = delete;

    /// Kills the program alone with SIGKILL, as a crash would end it (xvfb-run then stops its X
    /// server). @return false if the group holds no sculpt-ui.
    bool killProgram();

private:
    int mGroup = -1;  // the process group's id: the pid of the shell started first in it
};

vtkSmartPointer<vtkImageData> readPng(const std::filesystem::path& path);
/// Share of pixels whose RGB differ by more than 8 in some channel.
double differingShare(vtkImageData* a, vtkImageData* b);

}  // namespace sculpt::test
