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

void prepareDirectory(const fs::path& dir)
{
    std::error_code ec;
    if (fs::is_directory(dir, ec)) return;
    const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, ec)) {
        throw InputError(dir.string() + ": parent directory '" + parent.string() + "' does not exist");
    }
    if (!fs::create_directory(dir, ec)) throw InputError(dir.string() + ": cannot create (" + ec.message() + ")");
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
