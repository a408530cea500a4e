// SPDX-License-Identifier: Apache-2.0
#include "core/base/written_outputs.h"

#include "core/base/disk_budget.h"
#include "core/base/errors.h"

namespace sculpt {

namespace fs = std::filesystem;

WrittenOutputs::~WrittenOutputs()
{
    if (mKept) return;
    std::error_code ec;
    for (const fs::path& file : mFiles) fs::remove(file, ec);
    for (auto dir = mDirectories.rbegin(); dir != mDirectories.rend(); ++dir) fs::remove(*dir, ec);  // if empty
}

void WrittenOutputs::directory(const fs::path& dir)
{
    std::error_code ec;
    if (fs::is_directory(dir, ec)) return;
    const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, ec))
        throw InputError(dir.string() + ": parent directory '" + parent.string() + "' does not exist");
    if (!fs::create_directory(dir, ec)) throw InputError(dir.string() + ": cannot create (" + ec.message() + ")");
    mDirectories.push_back(dir);
}

const fs::path& WrittenOutputs::file(const fs::path& path)
{
    std::error_code ec;
    if (!fs::exists(path, ec)) mFiles.push_back(path);
    return path;
}

void WrittenOutputs::requireRoomFor(long long others, double scale, const std::string& what) const
{
    if (mFiles.empty() || others <= 0) return;
    std::error_code ec;
    double bytes = 0.0;
    for (const fs::path& file : mFiles) {
        const std::uintmax_t size = fs::file_size(file, ec);
        if (!ec) bytes += double(size);
    }
    const fs::path dir = mFiles.front().has_parent_path() ? mFiles.front().parent_path() : fs::path(".");
    requireDiskSpace(bytes * scale * double(others), dir, what);
}

}  // namespace sculpt
