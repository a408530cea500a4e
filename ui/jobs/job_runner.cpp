#include "ui/jobs/job_runner.h"

#include "core/base/errors.h"

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
    if (job->cancelled()) return {Ending::Cancelled, job->label(), {}};
    if (!job->succeeded()) return {Ending::Failed, job->label(), job->error()};
    try {
        land();
    } catch (const InputError& e) {  // the result does not fit (a grid too large to mesh)
        return {Ending::Failed, job->label(), e.what()};
    }
    return {Ending::Finished, job->label(), {}};
}

}  // namespace sculpt::ui
