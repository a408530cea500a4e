// SPDX-License-Identifier: Apache-2.0
#include "tests/support/cgal_data.h"

#include "tests/support/temp_dir.h"

#include <cstdlib>
#include <memory>

namespace sculpt::test {

namespace fs = std::filesystem;

namespace {

const char* kArchive = "/usr/share/doc/libcgal-dev/data.tar.gz";

const TempDir& extractionDir()
{
    static const auto dir = std::make_unique<TempDir>();
    return *dir;
}

}  // namespace

fs::path cgalData(const std::string& name)
{
    if (!fs::exists(kArchive)) return {};
    const fs::path member = fs::path("data") / name;
    const fs::path extracted = extractionDir() / member.string();
    if (!fs::exists(extracted)) {
        const std::string command = std::string("tar -xzf ") + kArchive + " -C '" + extractionDir().path().string() +
                                    "' '" + member.string() + "'";
        if (std::system(command.c_str()) != 0 || !fs::exists(extracted)) return {};
    }
    return extracted;
}

}  // namespace sculpt::test
