// SPDX-License-Identifier: Apache-2.0
#include "core/base/private_directory.h"

#include "core/base/errors.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace sculpt {

namespace fs = std::filesystem;

void makePrivateDirectory(const fs::path& dir)
{
    fs::path at;
    for (const fs::path& part : dir) {
        at /= part;
        if (mkdir(at.c_str(), 0700) == 0) {
            chmod(at.c_str(), 0700);  // mkdir's mode passed through the umask
        } else if (errno != EEXIST) {
            throw InputError(at.string() + ": cannot create the directory (" + std::strerror(errno) + ")");
        }
    }
    std::error_code ec;
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace, ec);
    if (ec) throw InputError(dir.string() + ": cannot make the directory private (" + ec.message() + ")");
}

}  // namespace sculpt
