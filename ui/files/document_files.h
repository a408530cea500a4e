// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file document_files.h
/// @brief The document as files: opened as a job (asking which level set of a file of several),
///        made new, saved, exported, recovered from its autosave, listed as recent; and the
///        questions that guard them ("save changes?", "recover?", "which level set?").

#include "ui/commands/commands.h"
#include "ui/document/recent_files.h"
#include "ui/jobs/job_runner.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sculpt::ui {

class Workspace;

class DocumentFiles {
public:
    /// "Which level set?": a file holding several, none named "surface".
    struct GridChoice {
        std::filesystem::path file;
        std::vector<std::string> grids;
    };
    /// What became of the command line's document since the last frame (followStart): nothing
    /// new, it landed (its chunks fill in from now), or its full detail is on screen.
    enum class Start { None, Landed, Shown };

    DocumentFiles(Workspace& work, const std::filesystem::path& stateDir);

    /// The command line's document (`path`, its level set `grid`) in place of the workspace's
    /// placeholder: its recovery copy offered if one is newer (the document opens as it is
    /// meanwhile), else opened as a job, the window up at once and a large model's preview
    /// shortly after. Empty: a new clay ball (an untitled recovery copy offered).
    void openAtStart(const std::filesystem::path& path, const std::string& grid);
    bool openingAtStart() const { return mOpeningAtStart; }
    /// Follows that opening once a frame with the job's `ending`; `shown`: its chunks are all on
    /// screen. A failure ends the program as a bad argument would (throws InputError, exit 2).
    Start followStart(JobRunner::Ending ending, const std::string& error, bool shown);

    /// Opens `path` as a job (the document stays if it fails); asks which level set if it
    /// holds several and `grid` names none.
    void open(const std::filesystem::path& path, const std::string& grid = {});
    /// Saves under `path`: the document takes the name, its recovery copies go.
    void saveTo(const std::filesystem::path& path);
    /// Writes the surface as a mesh file, as a job.
    void exportMesh(const std::filesystem::path& path);
    /// Writes the pieces as a label map on the kept scan's lattice (File > Export Segmentation),
    /// as a job. @throws InputError if the document keeps no scan.
    void exportLabels(const std::filesystem::path& path);
    /// The document's path with `extension` ("doc.ply"), or `fallback` for an unnamed document.
    std::string besideDocument(const char* extension, const char* fallback) const;

    /// False when there are unsaved changes: "save changes?" is asked, and `again` runs once
    /// answered (through `execute`, given with the answer).
    bool guardUnsaved(Command again);
    /// Save or discard (or neither: cancelled), then the command held runs by `execute`.
    void answerUnsaved(bool save, bool discard, const std::function<void(Command)>& execute);
    /// Opens the recovery copy offered (accept) or deletes it.
    void recover(bool accept);
    /// Opens the level set chosen (nothing: the choice was cancelled).
    void chooseGrid(std::optional<std::string> grid);

    const std::optional<Command>& askingUnsaved() const { return mAfterUnsaved; }
    const std::optional<std::filesystem::path>& offeringRecovery() const { return mRecovery; }
    const std::optional<GridChoice>& askingGrid() const { return mGridChoice; }
    /// One of the questions is open: it takes every key.
    bool asking() const { return mAfterUnsaved || mRecovery || mGridChoice; }
    RecentFiles& recent() { return mRecent; }

    /// The questions open, in the window's report.
    void report(nlohmann::json& out) const;

private:
    void openInJob(const std::filesystem::path& path, const std::string& grid);

    Workspace& mWork;
    RecentFiles mRecent;
    std::optional<Command> mAfterUnsaved;            // asking "save changes?" before this command
    bool mUnsavedAnswered = false;                   // ... answered: the command it held runs
    std::optional<std::filesystem::path> mRecovery;  // offering to recover this file
    std::optional<GridChoice> mGridChoice;
    bool mOpeningAtStart = false;
};

}  // namespace sculpt::ui
