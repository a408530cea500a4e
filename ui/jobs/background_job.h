#pragma once
/// @file background_job.h
/// @brief A long whole-model operation (a filter, a morph) run off the UI thread, so frames
///        keep coming: it works on its own copy of the model, reports progress through the
///        engine's Progress callback and stops at the next report after cancel(). The UI polls
///        it every frame and lands the result as one undo step; a cancelled or failed job leaves
///        the document exactly as it was.

#include "core/base/progress.h"
#include "core/field/field_image.h"

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace sculpt::ui {

class BackgroundJob {
public:
    /// The work: reads what it captured (its own copies), returns the new model.
    using Work = std::function<FieldImage(const Progress& progress)>;

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

    /// Once finished: the result (nullopt if cancelled or failed), taken once.
    std::optional<FieldImage> takeResult();
    /// Once finished: why there is no result ("" if cancelled or there is one).
    std::string error() const;
    /// Once finished: whether it stopped because cancel() asked.
    bool cancelled() const { return mWasCancelled.load(); }

private:
    void run(const Work& work);

    std::string mLabel;
    std::atomic<double> mProgress{0.0};
    std::atomic<bool> mCancel{false}, mFinished{false}, mWasCancelled{false};
    mutable std::mutex mMutex;  // guards the result and the error
    std::optional<FieldImage> mResult;
    std::string mError;
    std::thread mThread;
};

}  // namespace sculpt::ui
