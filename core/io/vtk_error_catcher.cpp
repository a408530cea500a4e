// SPDX-License-Identifier: Apache-2.0
#include "core/io/vtk_error_catcher.h"

#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkObjectFactory.h>

#include <algorithm>
#include <sstream>

namespace sculpt {

/// The watched object's errors (and warnings).
class VtkErrorCatcher::Observer : public vtkCommand {
public:
    static Observer* New() { return new Observer; }
    void Execute(vtkObject*, unsigned long event, void* data) override
    {
        const auto* text = static_cast<const char*>(data);
        if (!text || (event == vtkCommand::WarningEvent && owner->tolerates(text))) return;
        if (message.empty()) message = text;
    }
    std::string message;
    VtkErrorCatcher* owner = nullptr;
};

/// Everything else VTK prints during the call: errors kept, the rest dropped.
class VtkErrorCatcher::Window : public vtkOutputWindow {
public:
    static Window* New();
    void DisplayText(const char*) override {}
    void DisplayErrorText(const char* text) override
    {
        if (message.empty() && text) message = text;
    }
    void DisplayWarningText(const char*) override {}
    void DisplayGenericWarningText(const char*) override {}
    void DisplayDebugText(const char*) override {}
    std::string message;
};

vtkStandardNewMacro(VtkErrorCatcher::Window);

VtkErrorCatcher::VtkErrorCatcher(vtkObject* watched, bool warningsToo, std::vector<std::string> tolerated)
    : mObserver(vtkSmartPointer<Observer>::New()), mWindow(vtkSmartPointer<Window>::New()),
      mPrevious(vtkOutputWindow::GetInstance()), mWatched(watched), mWarningsToo(warningsToo),
      mTolerated(std::move(tolerated))
{
    mObserver->owner = this;
    mWatched->AddObserver(vtkCommand::ErrorEvent, mObserver);
    if (warningsToo) mWatched->AddObserver(vtkCommand::WarningEvent, mObserver);
    vtkOutputWindow::SetInstance(mWindow);
    std::ostringstream id;
    id << "sculpt-catcher-" << static_cast<const void*>(this);
    mLogId = id.str();
    vtkLogger::AddCallback(
        mLogId.c_str(),
        [](void* self, const vtkLogger::Message& m) {
            auto* catcher = static_cast<VtkErrorCatcher*>(self);
            const bool counts =
                m.verbosity <= (catcher->mWarningsToo ? vtkLogger::VERBOSITY_WARNING : vtkLogger::VERBOSITY_ERROR);
            if (!counts || !m.message) return;
            if (m.verbosity == vtkLogger::VERBOSITY_WARNING && catcher->tolerates(m.message)) return;
            if (catcher->mLogged.empty()) catcher->mLogged = m.message;
        },
        this, vtkLogger::VERBOSITY_WARNING);
}

VtkErrorCatcher::~VtkErrorCatcher()
{
    vtkLogger::RemoveCallback(mLogId.c_str());
    vtkOutputWindow::SetInstance(mPrevious);
    mWatched->RemoveObserver(mObserver);
}

bool VtkErrorCatcher::tolerates(const char* text)
{
    const std::string message(text);
    for (const std::string& fragment : mTolerated) {
        if (message.find(fragment) == std::string::npos) continue;
        if (std::find(mToleratedSeen.begin(), mToleratedSeen.end(), fragment) == mToleratedSeen.end())
            mToleratedSeen.push_back(fragment);
        return true;
    }
    return false;
}

const std::string& VtkErrorCatcher::message() const
{
    if (!mObserver->message.empty()) return mObserver->message;
    return mWindow->message.empty() ? mLogged : mWindow->message;
}

void quietVtkLogger() { vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); }

}  // namespace sculpt
