// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"

#include "core/base/errors.h"
#include "core/base/interrupt_cleanup.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <string>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// A hidden sibling that keeps the extension: some writers (VTK's) append theirs otherwise.
fs::path temporarySibling(const fs::path& target)
{
    static std::atomic<unsigned> counter{0};
    const std::string name = "." + target.stem().string() + ".tmp-" + std::to_string(getpid()) + "-" +
                             std::to_string(counter++) + target.extension().string();
    return target.has_parent_path() ? target.parent_path() / name : fs::path(name);
}

/// fsync of `path` opened with `flags`; false (errno set) if it cannot be opened or flushed.
bool flushToDisk(const fs::path& path, int flags)
{
    const int fd = open(path.c_str(), flags | O_CLOEXEC);
    if (fd < 0) return false;
    const bool flushed = fsync(fd) == 0;
    const int error = errno;
    close(fd);
    errno = error;
    return flushed;
}

}  // namespace

void AtomicFile::checkTarget(const fs::path& target)
{
    if (target.empty()) throw InputError("no output file given");
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        throw InputError(target.string() + ": directory '" + dir.string() + "' does not exist");
    }
    if (fs::is_directory(target, ec)) {
        throw InputError(target.string() + ": is a directory, expected a file name");
    }
}

AtomicFile::AtomicFile(fs::path target) : mTarget(std::move(target))
{
    checkTarget(mTarget);
    mTemporary = temporarySibling(mTarget);
    mTicket = registerTemporary(mTemporary);  // before it exists: an interruption never leaves it
    try {
        createWithMode();
    } catch (...) {
        forgetTemporary(mTicket);
        throw;
    }
}

void AtomicFile::createWithMode()
{
    const int fd = open(mTemporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throw InputError(mTarget.string() + ": cannot write (" + std::strerror(errno) + ")");
    const fs::path dir = mTarget.has_parent_path() ? mTarget.parent_path() : fs::path(".");
    struct stat existing {};
    if (stat(dir.c_str(), &existing) == 0 && (existing.st_mode & 077) == 0) {
        fchmod(fd, 0600);
    } else if (stat(mTarget.c_str(), &existing) == 0) {
        fchmod(fd, existing.st_mode & 07777);
    }
    close(fd);
}

AtomicFile::~AtomicFile()
{
    if (!mCommitted) {
        std::error_code ignored;
        fs::remove(mTemporary, ignored);
    }
    forgetTemporary(mTicket);
}

void AtomicFile::commit()
{
    // On disk before it replaces the old file, and the rename on disk before we say it is done: a
    // power cut then leaves the old document or the new one, never an empty one.
    if (!flushToDisk(mTemporary, O_RDONLY))
        throw InputError(mTarget.string() + ": cannot write (" + std::strerror(errno) + ")");
    std::error_code ec;
    fs::rename(mTemporary, mTarget, ec);
    if (ec) throw InputError(mTarget.string() + ": cannot write (" + ec.message() + ")");
    mCommitted = true;
    forgetTemporary(mTicket);
    mTicket = -1;
    flushToDisk(mTarget.has_parent_path() ? mTarget.parent_path() : fs::path("."), O_RDONLY | O_DIRECTORY);
}

void writeFileAtomically(const fs::path& target, const std::string& text)
{
    AtomicFile file(target);
    {
        std::ofstream out(file.temporaryPath(), std::ios::binary);
        out << text;
        out.flush();
        if (!out) throw InputError(target.string() + ": cannot write (disk full or not writable?)");
    }
    file.commit();
}

}  // namespace sculpt
