// SPDX-License-Identifier: Apache-2.0
#include "ui/document/file_listing.h"

#include "core/base/file_extension.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

std::time_t toTimeT(fs::file_time_type t)
{
    // C++17 has no clock_cast: carry the offset between the two clocks over.
    const auto system = std::chrono::time_point_cast<std::chrono::system_clock::duration>(
        t - fs::file_time_type::clock::now() + std::chrono::system_clock::now());
    return std::chrono::system_clock::to_time_t(system);
}

bool endsWithSeparator(const std::string& typed) { return !typed.empty() && (typed.back() == '/'); }

/// The entry for `item` if the listing shows it.
bool describe(const fs::directory_entry& item, const FileKinds& kinds, FileEntry& entry)
{
    std::error_code ec;
    entry.name = item.path().filename().string();
    if (entry.name.empty() || entry.name[0] == '.') return false;
    entry.folder = item.is_directory(ec);
    if (!entry.folder && !(item.is_regular_file(ec) && kinds.acceptsFile(item.path()))) return false;
    entry.bytes = entry.folder ? 0 : item.file_size(ec);
    const fs::file_time_type written = item.last_write_time(ec);
    entry.modified = ec ? 0 : toTimeT(written);
    return true;
}

}  // namespace

bool FileKinds::acceptsFile(const fs::path& path) const
{
    const std::string ext = lowerExtension(path);
    if (ext.empty()) return extensionless || extensions.empty();
    return extensions.empty() || std::find(extensions.begin(), extensions.end(), ext) != extensions.end();
}

DirectoryListing listDirectory(const fs::path& directory, const FileKinds& kinds, std::size_t limit)
{
    DirectoryListing listing{directory, {}, false, {}};
    std::error_code ec;
    fs::directory_iterator it(directory.empty() ? fs::path(".") : directory,
                              fs::directory_options::skip_permission_denied, ec);
    if (ec) listing.error = ec.message();
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
        if (listing.entries.size() == limit) {
            listing.truncated = true;
            break;
        }
        FileEntry entry;
        if (describe(*it, kinds, entry)) listing.entries.push_back(std::move(entry));
    }
    std::sort(listing.entries.begin(), listing.entries.end(),
              [](const FileEntry& a, const FileEntry& b) { return a.folder != b.folder ? a.folder : a.name < b.name; });
    return listing;
}

fs::path expandHome(const std::string& typed)
{
    const char* home = std::getenv("HOME");
    if (home && (typed == "~" || typed.rfind("~/", 0) == 0))
        return fs::path(home) / typed.substr(std::min<std::size_t>(2, typed.size()));
    return typed;
}

fs::path directoryOf(const std::string& typed)
{
    const fs::path path = expandHome(typed);
    std::error_code ec;
    if (endsWithSeparator(typed) || fs::is_directory(path, ec)) return path;
    return path.parent_path();
}

std::string completePath(const std::string& typed, const FileKinds& kinds)
{
    const fs::path path = expandHome(typed);
    if (endsWithSeparator(typed) && typed.size() > 1) return typed;  // nothing typed of a name yet
    const std::string stem = path.filename().string();
    if (stem.empty()) return typed;
    std::string shared;
    bool any = false, loneFolder = false;
    for (const FileEntry& entry : listDirectory(path.parent_path(), kinds).entries) {
        if (entry.name.rfind(stem, 0) != 0) continue;
        if (!any) shared = entry.name, loneFolder = entry.folder;
        else {
            shared.resize(std::mismatch(shared.begin(), shared.end(), entry.name.begin(), entry.name.end()).first -
                          shared.begin());
            loneFolder = false;
        }
        any = true;
    }
    if (!any) return typed;
    const std::string typedDirectory = typed.substr(0, typed.size() - stem.size());
    return typedDirectory + shared + (loneFolder ? "/" : "");
}

}  // namespace sculpt::ui
