// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file atomic_file.h
/// @brief Write a file so that a crash never leaves it half written.
///
/// Writers write to a temporary sibling (same directory, hence same file system), then
/// commit() flushes it to disk (fsync) and renames it over the target in one step, then flushes
/// the directory: after a power cut the target holds the old content or the new, never a part.
/// If commit() is never reached (an exception, a crash before it), the temporary is removed and
/// the target keeps its previous content; an interruption removes it too (interrupt_cleanup.h).
/// A file in a private directory (no access for group or others, such as the 0700 state
/// directory) is written 0600, whatever the umask; elsewhere the new file keeps the permissions
/// of the one it replaces, so saving never widens who may read a document.

#include <filesystem>
#include <string>

namespace sculpt {

class AtomicFile {
public:
    /// Prepares to write `target`. @throws InputError if its directory does not exist.
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Where the writer must write.
    const std::filesystem::path& temporaryPath() const { return mTemporary; }
    /// Replaces the target with the temporary, on disk. @throws InputError if the flush or the
    /// rename fails (the target is then unchanged).
    void commit();

    /// @throws InputError naming `target` if its directory does not exist or it is a directory.
    /// Call before long work so a bad output path fails fast.
    static void checkTarget(const std::filesystem::path& target);

private:
    /// Creates the empty temporary with the target's permissions: writers then open it in place.
    void createWithMode();

    std::filesystem::path mTarget;
    std::filesystem::path mTemporary;
    bool mCommitted = false;
    int mTicket = -1;  ///< its registration for removal on an interruption
};

/// Writes `text` to `target` through an AtomicFile.
/// @throws InputError naming the file if its directory is missing or the write fails.
void writeFileAtomically(const std::filesystem::path& target, const std::string& text);

}  // namespace sculpt
