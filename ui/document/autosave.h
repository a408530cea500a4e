// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file autosave.h
/// @brief Nothing lost: the document is copied to a recovery file every few minutes while it
///        has unsaved changes (never in the middle of a stroke); a recovery file newer than its
///        document is offered back on the next start, and removed on save or a clean quit.
///
/// Recovery files live under the user's state directory ($XDG_STATE_HOME/sculpt, else
/// ~/.local/state/sculpt), in recovery/, named after the document's absolute path.

#include <filesystem>
#include <optional>

namespace sculpt {
class Document;
}  // namespace sculpt

namespace sculpt::ui {

class Autosave {
public:
    static constexpr double kDefaultIntervalSeconds = 120.0;

    /// @param stateDir where recovery/ goes (see stateDirectory()).
    Autosave(std::filesystem::path stateDir, double intervalSeconds);

    /// $XDG_STATE_HOME/sculpt, else $HOME/.local/state/sculpt, else ./.sculpt-state.
    static std::filesystem::path stateDirectory();

    /// Writes the recovery file when the document changed since the last one and the interval
    /// has passed. @return true if it wrote. A failure (disk full) is reported, never thrown.
    bool tick(const Document& document, double nowSeconds, bool strokeActive, std::string& error);
    /// Writes the recovery file now if the document changed since the last one (before work
    /// that could end the session, such as reading a file). @return true if it wrote.
    bool save(const Document& document, std::string& error);

    /// The recovery file of the document at `documentPath` (empty: untitled).
    std::filesystem::path recoveryFile(const std::filesystem::path& documentPath) const;
    /// The recovery file of that document, if one exists and is newer than the document.
    std::optional<std::filesystem::path> pending(const std::filesystem::path& documentPath) const;
    /// Removes that document's recovery file.
    void discard(const std::filesystem::path& documentPath);

    double intervalSeconds() const { return mInterval; }

private:
    bool needsWrite(const Document& document) const;

    std::filesystem::path mDir;
    double mInterval;
    double mLastWrite = 0.0;
    std::uint64_t mWrittenRevision = 0;
    bool mWrittenOnce = false;
};

}  // namespace sculpt::ui
