// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file workspace.h
/// @brief The document being worked on and the one way its changes land: a whole-model edit or
///        a new document, each as the window's one job, the notice saying what became of it; why
///        an edit must wait; the recovery copy kept while it has unsaved changes.

#include "sculpt/session/document.h"
#include "ui/document/autosave.h"
#include "ui/document/open_preview.h"
#include "ui/jobs/job_runner.h"
#include "ui/jobs/model_edit.h"
#include "ui/status/notices.h"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace sculpt::ui {

class CommandRegistry;

class Workspace {
public:
    /// Sees a document's field once it is read, before its mesh is made: a large model shows a
    /// coarse preview meanwhile.
    using FieldReady = std::function<void(const FieldImage& field)>;
    using DocumentMaker = std::function<std::unique_ptr<Document>(const Progress& progress, const FieldReady& ready)>;
    /// What the window adds: why an edit must wait for it (a gesture, an open mode) or "", and
    /// what it does when another document takes this one's place (`frameIt`: the camera frames it).
    struct Hooks {
        std::function<std::string()> waitElsewhere;
        std::function<void(bool frameIt)> replaced;
    };

    Workspace(std::unique_ptr<Document> document, Autosave autosave, std::size_t previewTriangles);
    void connect(Hooks hooks) { mHooks = std::move(hooks); }

    Document& document() { return *mDocument; }
    const Document& document() const { return *mDocument; }
    /// Another document takes this one's place.
    void replace(std::unique_ptr<Document> document, bool frameIt);
    JobRunner& jobs() { return mJobs; }
    const JobRunner& jobs() const { return mJobs; }
    Notices& notices() { return mNotices; }
    const Notices& notices() const { return mNotices; }
    Autosave& autosave() { return mAutosave; }

    /// Why an edit of the document must wait (a job runs, a gesture, an open mode), or "".
    std::string waitReason() const;
    /// True (with waitReason as the notice) if an edit of the document must wait.
    bool busy();

    /// Runs `edit` on a copy of the model as the job; its result lands as one undo step, in the
    /// stroke log when it carries a script event, "LABEL done (Ctrl+Z undoes it)".
    void startEdit(ModelEdit edit);
    /// Runs `make` as the job; the document it makes replaces this one (the view stays where a
    /// preview framed it), and `landed` (called then) says so. `make` hands its field to `ready`
    /// before meshing it.
    void startDocument(std::string label, DocumentMaker make, std::function<std::string()> landed);
    /// Runs `work` (Progress -> Result) as the job; once it succeeded, `land` (Result ->
    /// std::string) lands its result in the document as one undo step on the UI thread and says
    /// what the notice adds, or "" (landed). A piece edit, a move, a push land so.
    template <typename Result, typename WorkFn, typename LandFn>
    void startUndoable(std::string label, WorkFn work, LandFn land)
    {
        startJob<Result>(label, std::move(work), [this, label, land = std::move(land)](Result result) {
            landed(label, land(std::move(result)));
        });
    }
    /// An edit landed as one undo step: "LABEL done[: WHAT] (Ctrl+Z undoes it)", the one notice
    /// every edit of the document ends with.
    void landed(const std::string& label, const std::string& what = {});
    /// Runs `work` (Progress -> Result) as the job, saying so; `land` (Result) takes its result
    /// on the UI thread once it succeeded.
    template <typename Result, typename WorkFn, typename LandFn>
    void startJob(std::string label, WorkFn work, LandFn land)
    {
        mNotices.say(label + "...");
        mJobs.start<Result>(std::move(label), std::move(work), std::move(land));
    }
    /// The preview of the document a job is making, once, when it is ready (the view shows it).
    std::optional<OpenPreview::Surface> takePreview();
    /// Lands a finished job's result (or says why there is none). @return how it ended.
    JobRunner::Outcome poll();

    /// Writes the recovery copy if it is due (never during a stroke). @return true if it wrote.
    bool autosaveIfDue(double now, bool stroking);
    /// Writes the recovery copy now, before a file is read: a reader that takes the process
    /// down must not take unsaved work.
    void autosaveNow();

    /// Undo and Redo.
    void addCommands(CommandRegistry& commands);
    /// The document, the job and the notices in the window's report.
    void report(nlohmann::json& out) const;

private:
    std::unique_ptr<Document> mDocument;
    Autosave mAutosave;
    std::size_t mPreviewTriangles;
    std::shared_ptr<OpenPreview> mPreview;  // of the job making a document, if one runs
    bool mPreviewTaken = false;             // ... and the view shows it
    std::size_t mPreviewsTaken = 0;         // reported: a large document showed one first
    JobRunner mJobs;
    Notices mNotices;
    Hooks mHooks;
};

}  // namespace sculpt::ui
