#include "sculpt/session/frame_files.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"

#include <algorithm>
#include <cstdio>

namespace sculpt {

namespace fs = std::filesystem;

fs::path framePath(const fs::path& dir, int index, const std::string& extension)
{
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.%s", index, extension.c_str());
    return dir / name;
}

std::vector<fs::path> documentsIn(const fs::path& dir)
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.is_regular_file() && lowerExtension(entry.path()) == ".vdb") files.push_back(entry.path());
    }
    if (files.empty()) throw InputError(dir.string() + ": no .vdb documents in this directory");
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace sculpt
