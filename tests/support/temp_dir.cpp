// SPDX-License-Identifier: Apache-2.0
#include "tests/support/temp_dir.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace sculpt::test {

TempDir::TempDir()
{
    std::string pattern = (std::filesystem::temp_directory_path() / "sculpt-test-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    mPath = pattern;
}

TempDir::~TempDir()
{
    std::error_code ignored;
    std::filesystem::remove_all(mPath, ignored);
}

std::vector<std::string> TempDir::entries() const { return entriesOf(mPath); }

std::vector<std::string> TempDir::entriesOf(const std::filesystem::path& dir)
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace sculpt::test
