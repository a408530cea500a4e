#pragma once
/// @file vtk_error_catcher.h
/// @brief Catches what a VTK reader reports instead of letting it print to stderr, so the
///        caller can turn it into an InputError naming the file. For VTK translation units only.

#include <vtkCommand.h>

#include <string>

namespace sculpt {

/// Observer of vtkCommand::ErrorEvent (and WarningEvent): keeps the first message.
class VtkErrorCatcher : public vtkCommand {
public:
    static VtkErrorCatcher* New() { return new VtkErrorCatcher; }
    void Execute(vtkObject*, unsigned long, void* data) override
    {
        if (message.empty() && data) message = static_cast<const char*>(data);
    }
    std::string message;
};

}  // namespace sculpt
