// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file progress_bar.h
/// @brief A progress bar on the terminal for long commands (nothing when stderr is not a TTY,
///        so logs and scripts stay clean).

#include "core/base/progress.h"

#include <string>

namespace sculpt::cli {

class ProgressBar {
public:
    explicit ProgressBar(std::string label);
    ~ProgressBar();  ///< ends the bar's line
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// The callback to hand to a core operation; never cancels.
    Progress callback();
    /// No bar from now on, even on a terminal (--quiet).
    static void hideAll();

private:
    void draw(double fraction);

    static bool sHidden;
    std::string mLabel;
    bool mEnabled;
    int mShownPercent = -1;
};

}  // namespace sculpt::cli
