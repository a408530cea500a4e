#include "core/base/atomic_file.h"

#include "core/base/errors.h"

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
    createWithMode();
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
}

void AtomicFile::commit()
{
    std::error_code ec;
    fs::rename(mTemporary, mTarget, ec);
    if (ec) throw InputError(mTarget.string() + ": cannot write (" + ec.message() + ")");
    mCommitted = true;
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
