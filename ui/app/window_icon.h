// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file window_icon.h
/// @brief The window's icon (X11 shows it in the title bar and the task switcher; Wayland takes
///        the launcher's): the application icon the build renders, read from where it is
///        installed beside the program, or from the build tree.

#include "ui/window/app_window.h"

#include <vector>

namespace sculpt::ui {

/// The icon's sizes found (none if none is: a missing icon is no error).
std::vector<IconImage> applicationIcon();

}  // namespace sculpt::ui
