// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file background_job.h
/// @brief A long operation (a filter, a morph, an import, opening or exporting) run off the UI
///        thread, so frames keep coming: it works on its own copies, reports progress through
///        the engine's Progress callback and stops at the next report after cancel(). The UI
///        polls it every frame and, once it succeeded, takes what it made (the work keeps its
///        result where the UI finds it); a cancelled or failed job leaves the document exactly as
///        it was.

#include "core/base/progress.h"

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace sculpt::ui {

class BackgroundJob {
public:
    /// The work: reads what it captured (its own copies) and stores what it makes there too.
    using Work = std::function<void(const Progress& progress)>;

    /// Starts `work` on a thread of its own. `label` names it ("smooth 10") in the UI.
    BackgroundJob(std::string label, Work work);
    /// Cancels and waits for the thread.
    ~BackgroundJob();
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;

    const std::string& label() const { return mLabel; }
    /// Fraction done in [0, 1], as last reported.
    double progress() const { return mProgress.load(); }
    /// Asks the work to stop at its next progress report.
    void cancel() { mCancel = true; }
    bool cancelRequested() const { return mCancel.load(); }
    bool finished() const { return mFinished.load(); }

    /// Once finished: whether the work ran to its end (neither cancelled nor failed).
    bool succeeded() const { return mSucceeded.load(); }
    /// Once finished: why it failed ("" if cancelled or it succeeded).
    std::string error() const;
    /// Once finished: whether it stopped because cancel() asked.
    bool cancelled() const { return mWasCancelled.load(); }

private:
    void run(const Work& work);

    std::string mLabel;
    std::atomic<double> mProgress{0.0};
    std::atomic<bool> mCancel{false}, mFinished{false}, mWasCancelled{false}, mSucceeded{false};
    mutable std::mutex mMutex;  // guards the error
    std::string mError;
    std::thread mThread;
};

}  // namespace sculpt::ui
