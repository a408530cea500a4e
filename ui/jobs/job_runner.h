// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file job_runner.h
/// @brief The window's one background job at a time and what becomes of its result: started
///        with the work (off the UI thread) and its landing (on the UI thread, once the work
///        succeeded), polled every frame.

#include "ui/jobs/background_job.h"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace sculpt::ui {

class JobRunner {
public:
    enum class Ending { Running, Finished, Cancelled, Failed };
    struct Outcome {
        Ending ending = Ending::Running;
        std::string label;
        std::string error;  ///< why it failed (the work's error, or its landing's)
    };

    /// Runs `work` (Progress -> Result) as the job; `land` (Result) takes the result once the
    /// work succeeded. A job still running is cancelled and waited for first.
    template <typename Result, typename WorkFn, typename LandFn>
    void start(std::string label, WorkFn work, LandFn land);

    bool running() const { return mJob != nullptr; }
    /// The job running, or nullptr.
    const BackgroundJob* job() const { return mJob.get(); }
    /// Asks the job to stop; whatever it worked on stays as it was.
    void cancel();
    /// If the job has finished: lands its result (when it succeeded) and says how it ended.
    Outcome poll();
    /// The job running (its label and progress) and how the last one ended, for the window's report.
    void report(nlohmann::json& out) const;

private:
    Ending mLastEnding = Ending::Running;  // Running: none has ended yet
    std::unique_ptr<BackgroundJob> mJob;
    std::function<void()> mLand;  // hands the finished work's result to its landing
};

template <typename Result, typename WorkFn, typename LandFn>
void JobRunner::start(std::string label, WorkFn work, LandFn land)
{
    mJob.reset();
    // Written by the job's thread before it reports finished, read after: no lock needed.
    auto result = std::make_shared<std::optional<Result>>();
    mJob = std::make_unique<BackgroundJob>(
        std::move(label), [result, work = std::move(work)](const Progress& p) { result->emplace(work(p)); });
    mLand = [result, land = std::move(land)] { land(std::move(**result)); };
}

}  // namespace sculpt::ui
