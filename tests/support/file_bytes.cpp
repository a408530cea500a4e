// SPDX-License-Identifier: Apache-2.0
#include "tests/support/file_bytes.h"

#include <fstream>
#include <iterator>

namespace sculpt::test {

std::string fileBytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeFileBytes(const std::filesystem::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

}  // namespace sculpt::test
