// SPDX-License-Identifier: Apache-2.0
#include "ui/workspace/workspace.h"

#include "ui/commands/command_registry.h"
#include "ui/input/input_event.h"
#include "ui/status/document_report.h"

#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include <iostream>

namespace sculpt::ui {

Workspace::Workspace(std::unique_ptr<Document> document, Autosave autosave, std::size_t previewTriangles)
    : mDocument(std::move(document)), mAutosave(std::move(autosave)), mPreviewTriangles(previewTriangles)
{}

void Workspace::replace(std::unique_ptr<Document> document, bool frameIt)
{
    mDocument = std::move(document);
    if (mHooks.replaced) mHooks.replaced(frameIt);
}

std::string Workspace::waitReason() const
{
    if (mJobs.running()) return "wait for " + mJobs.job()->label() + " to finish, or press Esc to cancel it";
    return mHooks.waitElsewhere ? mHooks.waitElsewhere() : std::string();
}

bool Workspace::busy()
{
    const std::string reason = waitReason();
    if (!reason.empty()) mNotices.say(reason);
    return !reason.empty();
}

void Workspace::startEdit(ModelEdit edit)
{
    // The job works on its own copy: the document stays as it is until the result lands.
    auto copy = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
    const std::string label = edit.label;
    startUndoable<FieldImage>(
        label, [copy, work = std::move(edit.work)](const Progress& p) { return work(std::move(*copy), p); },
        [this, label, summary = std::move(edit.summary), scripted = std::move(edit.scripted),
         takes = edit.takes](FieldImage result) {
            if (takes == ModelEdit::Takes::Mask) mDocument->replaceMask(result.maskPtr(), label, *scripted);
            else mDocument->replaceField(std::move(result), label, scripted);
            return summary ? summary() : std::string();
        });
}

void Workspace::landed(const std::string& label, const std::string& what)
{
    mNotices.say(label + " done" + (what.empty() ? "" : ": " + what) + " (Ctrl+Z undoes it)");
}

void Workspace::startDocument(std::string label, DocumentMaker make, std::function<std::string()> landed)
{
    auto preview = mPreview = std::make_shared<OpenPreview>(mPreviewTriangles);
    mPreviewTaken = false;
    startJob<std::unique_ptr<Document>>(
        std::move(label),
        [make = std::move(make), preview](const Progress& p) {
            return make(p, [&](const FieldImage& f) { preview->offer(f); });
        },
        [this, landed = std::move(landed)](std::unique_ptr<Document> document) {
            replace(std::move(document), !mPreviewTaken);  // a preview was framed: the view stays as it is
            mNotices.say(landed());
        });
}

std::optional<OpenPreview::Surface> Workspace::takePreview()
{
    std::optional<OpenPreview::Surface> preview = mPreview ? mPreview->take() : std::nullopt;
    if (preview) {
        ++mPreviewsTaken;
        mPreviewTaken = true;
    }
    return preview;
}

JobRunner::Outcome Workspace::poll()
{
    const JobRunner::Outcome outcome = mJobs.poll();
    if (outcome.ending == JobRunner::Ending::Cancelled)
        mNotices.say(outcome.label + " cancelled: the model is as it was");
    if (outcome.ending == JobRunner::Ending::Failed) mNotices.fail(outcome.error);
    if (outcome.ending != JobRunner::Ending::Running) mPreview.reset();
    return outcome;
}

bool Workspace::autosaveIfDue(double now, bool stroking)
{
    std::string error;
    const bool wrote = mAutosave.tick(*mDocument, now, stroking, error);
    if (wrote) {
        mNotices.say("autosaved to " + mAutosave.recoveryFile(mDocument->path()).string());
        std::cout << "sculpt-ui: " << mNotices.notice() << std::endl;
    }
    if (!error.empty()) mNotices.say(error);
    return wrote || !error.empty();
}

void Workspace::autosaveNow()
{
    std::string error;
    if (mAutosave.save(*mDocument, error))
        std::cout << "sculpt-ui: autosaved to " << mAutosave.recoveryFile(mDocument->path()).string() << std::endl;
    if (!error.empty()) mNotices.say(error);
}

void Workspace::addCommands(CommandRegistry& commands)
{
    const auto undoable = [this](bool redo) {
        if (const std::string reason = waitReason(); !reason.empty()) return reason;
        const bool none = redo ? mDocument->redoLabels().empty() : mDocument->undoLabels().empty();
        return none ? std::string(redo ? "nothing to redo" : "nothing to undo") : std::string();
    };
    commands.add({Command::Undo,
                  "Undo",
                  "Undo the last stroke",
                  {{GLFW_KEY_Z, kControl}},
                  [undoable] { return undoable(false); },
                  [this] { mDocument->undo(); }});
    commands.add({Command::Redo,
                  "Redo",
                  "Redo the stroke undone last",
                  {{GLFW_KEY_Z, kControl | kShift}, {GLFW_KEY_Y, kControl}},
                  [undoable] { return undoable(true); },
                  [this] { mDocument->redo(); }});
}

void Workspace::report(nlohmann::json& out) const
{
    reportDocument(out, *mDocument);
    mJobs.report(out);
    mNotices.report(out);
    out["previews_shown"] = mPreviewsTaken;
}

}  // namespace sculpt::ui
