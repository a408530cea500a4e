// SPDX-License-Identifier: Apache-2.0
#include "core/base/file_extension.h"

#include <algorithm>
#include <cctype>

namespace sculpt {

std::string lowerExtension(const std::filesystem::path& path)
{
    std::string ext = path.extension().string();
    if (ext == ".gz" || ext == ".GZ") ext = path.stem().extension().string() + ext;
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace sculpt
