// SPDX-License-Identifier: Apache-2.0
#include "ui/document/recent_files.h"

#include "core/base/atomic_file.h"
#include "core/base/private_directory.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace sculpt::ui {

namespace fs = std::filesystem;

RecentFiles::RecentFiles(fs::path stateDir) : mFile(std::move(stateDir) / "recent.json")
{
    std::ifstream in(mFile);
    if (!in) return;
    const nlohmann::json list = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!list.is_array()) return;
    for (const auto& entry : list) {
        if (entry.is_string() && mEntries.size() < kMaxEntries) mEntries.emplace_back(entry.get<std::string>());
    }
}

void RecentFiles::add(const fs::path& path)
{
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    mEntries.erase(std::remove(mEntries.begin(), mEntries.end(), absolute), mEntries.end());
    mEntries.insert(mEntries.begin(), absolute);
    if (mEntries.size() > kMaxEntries) mEntries.resize(kMaxEntries);
    nlohmann::json list = nlohmann::json::array();
    for (const fs::path& entry : mEntries) list.push_back(entry.string());
    try {
        makePrivateDirectory(mFile.parent_path());
        writeFileAtomically(mFile, list.dump(1) + "\n");
    } catch (const std::exception&) {
        // Not being able to remember recent files must not stop a save.
    }
}

}  // namespace sculpt::ui
