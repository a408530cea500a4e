// SPDX-License-Identifier: Apache-2.0
#include "ui/app/window_icon.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

/// The hicolor folders to look in: installed (bin/../share/icons/hicolor), then the build tree's.
std::vector<fs::path> iconThemes()
{
    std::error_code error;
    const fs::path program = fs::read_symlink("/proc/self/exe", error);
    std::vector<fs::path> themes;
    if (!error) themes.push_back(program.parent_path().parent_path() / "share/icons/hicolor");
    themes.push_back(SCULPT_BUILD_ICONS);
    return themes;
}

/// A PNG's pixels as windows want them: RGBA, 8 bits, top row first. Empty if unreadable.
IconImage rgbaPixels(const fs::path& file)
{
    vtkNew<vtkPNGReader> reader;
    if (!reader->CanReadFile(file.c_str())) return {};
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    const int* dims = image->GetDimensions();
    const int channels = image->GetNumberOfScalarComponents();
    if (image->GetScalarType() != VTK_UNSIGNED_CHAR || channels < 3 || dims[0] < 1 || dims[1] < 1) return {};
    const int width = dims[0], height = dims[1];
    IconImage icon{width, height, std::vector<unsigned char>(std::size_t(width) * height * 4)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto* source = static_cast<const unsigned char*>(image->GetScalarPointer(x, height - 1 - y, 0));
            unsigned char* target = &icon.rgba[(std::size_t(y) * width + x) * 4];
            for (int c = 0; c < 4; ++c) target[c] = c < channels ? source[c] : 255;
        }
    return icon;
}

}  // namespace

std::vector<IconImage> applicationIcon()
{
    for (const fs::path& theme : iconThemes()) {
        std::vector<IconImage> sizes;
        for (const char* size : {"48x48", "64x64", "128x128"}) {
            IconImage image = rgbaPixels(theme / size / "apps" / (SCULPT_APP_ID ".png"));
            if (!image.rgba.empty()) sizes.push_back(std::move(image));
        }
        if (!sizes.empty()) return sizes;
    }
    return {};
}

}  // namespace sculpt::ui
