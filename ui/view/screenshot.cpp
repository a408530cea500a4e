// SPDX-License-Identifier: Apache-2.0
#include "ui/view/screenshot.h"

#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>
#include <vtk_glew.h>  // the OpenGL calls made here, as VTK loads them (no other GL header)

namespace sculpt::ui {

bool writeScreenshot(const std::filesystem::path& path, int width, int height)
{
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(width, height, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image->GetScalarPointer());  // bottom row first, as VTK
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName(path.c_str());
    writer->SetInputData(image);
    writer->Write();
    return writer->GetErrorCode() == 0;
}

}  // namespace sculpt::ui
