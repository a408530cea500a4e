// SPDX-License-Identifier: Apache-2.0
#include "ui/jobs/background_job.h"

#include "core/base/errors.h"

#include <exception>

namespace sculpt::ui {

BackgroundJob::BackgroundJob(std::string label, Work work)
    : mLabel(std::move(label)), mThread([this, work = std::move(work)] { run(work); })
{}

BackgroundJob::~BackgroundJob()
{
    cancel();
    if (mThread.joinable()) mThread.join();
}

void BackgroundJob::run(const Work& work)
{
    const Progress progress = [this](double fraction) {
        mProgress = fraction;
        return !mCancel.load();
    };
    try {
        work(progress);
        mSucceeded = true;
    } catch (const Cancelled&) {
        mWasCancelled = true;
    } catch (const InputError& e) {
        const std::lock_guard<std::mutex> lock(mMutex);
        mError = e.what();
    } catch (const std::exception& e) {
        const std::lock_guard<std::mutex> lock(mMutex);
        mError = mLabel + " failed: " + e.what();
    }
    mProgress = 1.0;
    mFinished = true;
}

std::string BackgroundJob::error() const
{
    const std::lock_guard<std::mutex> lock(mMutex);
    return mError;
}

}  // namespace sculpt::ui
