// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file headless_app.h
/// @brief The whole window (SculptApp) in the test's own process on a HeadlessWindow: input
///        replayed through the same handle() as live input, nothing drawn, no display needed.

#include "tests/support/temp_dir.h"
#include "tests/support/ui_events.h"
#include "ui/app/sculpt_app.h"

#include <string>

namespace sculpt::test {

/// The default clay ball (radius 50 at the origin) at 1280x800 in the opening view: its centre.
constexpr double kCentreX = 640, kCentreY = 400;

/// Options for a replay in `dir`: its own state directory, `document` opened (empty: the ball).
ui::AppOptions headlessOptions(const TempDir& dir, const std::string& document = "");

/// Replays `events` (written to dir/events.json) in a 1280x800 headless SculptApp with
/// `options`. @return its exit status.
int playHeadless(const TempDir& dir, const UiEvents& events, ui::AppOptions options);

}  // namespace sculpt::test
