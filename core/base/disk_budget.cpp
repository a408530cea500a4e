// SPDX-License-Identifier: Apache-2.0
#include "core/base/disk_budget.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"

namespace sculpt {

void requireDiskSpace(double bytes, const std::filesystem::path& dir, const std::string& what)
{
    std::error_code ec;
    const std::filesystem::space_info space = std::filesystem::space(dir, ec);
    if (ec) return;  // the write itself will say what is wrong with the place
    const double free = double(space.available);
    if (bytes > free) {
        throw InputError(dir.string() + ": " + what + " need about " + formatBytes(bytes) + " but only " +
                         formatBytes(free) + " is free there");
    }
}

}  // namespace sculpt
