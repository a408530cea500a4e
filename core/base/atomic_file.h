#pragma once
/// @file atomic_file.h
/// @brief Write a file so that a crash never leaves it half written.
///
/// Writers write to a temporary sibling (same directory, hence same file system), then
/// commit() renames it over the target in one step. If commit() is never reached (an exception,
/// a crash before it), the temporary is removed and the target keeps its previous content.

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
    /// Replaces the target with the temporary. @throws InputError if the rename fails.
    void commit();

    /// @throws InputError naming `target` if its directory does not exist or it is a directory.
    /// Call before long work so a bad output path fails fast.
    static void checkTarget(const std::filesystem::path& target);

private:
    std::filesystem::path mTarget;
    std::filesystem::path mTemporary;
    bool mCommitted = false;
};

/// Writes `text` to `target` through an AtomicFile.
/// @throws InputError naming the file if its directory is missing or the write fails.
void writeFileAtomically(const std::filesystem::path& target, const std::string& text);

}  // namespace sculpt
