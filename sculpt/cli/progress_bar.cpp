// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace sculpt::cli {

bool ProgressBar::sHidden = false;

ProgressBar::ProgressBar(std::string label) : mLabel(std::move(label)), mEnabled(!sHidden && isatty(STDERR_FILENO) != 0)
{}

void ProgressBar::hideAll() { sHidden = true; }

ProgressBar::~ProgressBar()
{
    if (mEnabled && mShownPercent >= 0) std::fputc('\n', stderr);
}

Progress ProgressBar::callback()
{
    return [this](double fraction) {
        draw(fraction);
        return true;
    };
}

void ProgressBar::draw(double fraction)
{
    const int percent = int(100.0 * std::clamp(fraction, 0.0, 1.0));
    if (!mEnabled || percent == mShownPercent) return;
    mShownPercent = percent;
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%", mLabel.c_str(), filled, "########################################",
                 kWidth - filled, "", percent);
    std::fflush(stderr);
}

}  // namespace sculpt::cli
