// SPDX-License-Identifier: Apache-2.0
#include "ui/jobs/job_runner.h"

#include "core/base/errors.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

void JobRunner::cancel()
{
    if (mJob) mJob->cancel();
}

JobRunner::Outcome JobRunner::poll()
{
    if (!mJob || !mJob->finished()) return {};
    const std::unique_ptr<BackgroundJob> job = std::move(mJob);
    const std::function<void()> land = std::move(mLand);
    Outcome outcome{Ending::Finished, job->label(), {}};
    if (job->cancelled()) outcome.ending = Ending::Cancelled;
    else if (!job->succeeded()) outcome = {Ending::Failed, job->label(), job->error()};
    else {
        try {
            land();
        } catch (const InputError& e) {  // the result does not fit (a grid too large to mesh)
            outcome = {Ending::Failed, job->label(), e.what()};
        }
    }
    mLastEnding = outcome.ending;
    return outcome;
}

void JobRunner::report(nlohmann::json& out) const
{
    out["job"] = mJob ? nlohmann::json{{"label", mJob->label()}, {"progress", mJob->progress()}} : nlohmann::json();
    constexpr const char* kEndings[] = {"", "finished", "cancelled", "failed"};
    out["last_job"] = kEndings[int(mLastEnding)];
}

}  // namespace sculpt::ui
