// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file vtk_error_catcher.h
/// @brief Catches what VTK reports during one call instead of letting it print to stderr, so
///        the caller can turn it into an InputError naming the file. For VTK translation units.
///
/// VTK's error macros do nothing at all once vtkObject::GlobalWarningDisplayOff() was called,
/// so nothing here (nor anywhere else) switches them off: errors are caught per call instead,
/// from the watched object's events, from the output window (replaced for the call's duration)
/// and from vtkLogger, where the pipeline's executives and some readers write. The programs keep
/// vtkLogger off stderr (quietVtkLogger), so what is caught is said once, naming the file.

#include "core/io/vtk_logging.h"

#include <vtkCommand.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace sculpt {

/// Keeps the first error VTK reported while it lived: through `watched`'s ErrorEvent (and
/// WarningEvent, if asked) or through VTK's output window.
class VtkErrorCatcher {
public:
    /// Warnings holding one of `tolerated` are not kept as the error but listed by tolerated():
    /// notes a reader makes about a file it still reads right.
    explicit VtkErrorCatcher(vtkObject* watched, bool warningsToo = false, std::vector<std::string> tolerated = {});
    ~VtkErrorCatcher();
    VtkErrorCatcher(const VtkErrorCatcher&) = delete;
    VtkErrorCatcher& operator=(const VtkErrorCatcher&) = delete;

    /// The first message, or "".
    const std::string& message() const;
    bool caught() const { return !message().empty(); }
    /// The tolerated warnings seen, each once.
    const std::vector<std::string>& tolerated() const { return mToleratedSeen; }

private:
    class Observer;
    class Window;
    vtkSmartPointer<Observer> mObserver;
    vtkSmartPointer<Window> mWindow;
    vtkSmartPointer<vtkOutputWindow> mPrevious;
    vtkObject* mWatched;
    std::string mLogId;
    std::string mLogged;  // the first error (or warning, if asked) vtkLogger saw
    bool mWarningsToo;
    std::vector<std::string> mTolerated, mToleratedSeen;
    /// Whether `text` is a tolerated warning (then noted).
    bool tolerates(const char* text);
};

}  // namespace sculpt
