// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file progress_log.h
/// @brief A Progress callback for tests: records every fraction reported and can ask to stop
///        at a given report.

#include "core/base/progress.h"

#include <cstddef>
#include <mutex>
#include <vector>

namespace sculpt::test {

class ProgressLog {
public:
    /// Says stop at report number `stopAt` (0 is the first); never if it is -1.
    explicit ProgressLog(int stopAt = -1) : mStopAt(stopAt) {}

    Progress callback()
    {
        return [this](double fraction) {
            const std::lock_guard<std::mutex> lock(mMutex);  // some passes report from several threads
            mFractions.push_back(fraction);
            return mStopAt < 0 || int(mFractions.size()) <= mStopAt;
        };
    }
    const std::vector<double>& fractions() const { return mFractions; }
    /// Every fraction in [0, 1], never falling.
    bool monotone() const
    {
        for (std::size_t i = 0; i < mFractions.size(); ++i) {
            if (mFractions[i] < 0.0 || mFractions[i] > 1.0 || (i && mFractions[i] < mFractions[i - 1])) return false;
        }
        return true;
    }

private:
    int mStopAt;
    std::mutex mMutex;
    std::vector<double> mFractions;
};

}  // namespace sculpt::test
