// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/script_replay.h"

#include "core/base/errors.h"
#include "sculpt/session/document.h"
#include "sculpt/session/model_filter.h"
#include "sculpt/session/piece_changes.h"

namespace sculpt {

namespace {

/// What a message calls the event ("'add' stroke", "cut", "piece edit"; undo and redo say so themselves).
std::string nameOf(const ScriptEvent& event)
{
    if (const auto* stroke = std::get_if<script::StrokeEvent>(&event))
        return "'" + std::string(brushToolName(stroke->stroke.brush.tool)) + "' stroke";
    if (const auto* cut = std::get_if<script::CutEvent>(&event)) return prismModeName(cut->mode);
    if (const auto* selection = std::get_if<script::MaskSelectionEvent>(&event))
        return std::string("mask ") + maskSelectionName(selection->selection.kind);
    if (std::holds_alternative<script::DrainEvent>(event)) return "drain";
    if (std::holds_alternative<script::MaskEvent>(event)) return "mask";
    if (std::holds_alternative<script::UndoEvent>(event) || std::holds_alternative<script::RedoEvent>(event)) return "";
    return "piece edit";
}

void replayStroke(Document& document, const script::StrokeEvent& event, ReplayReport& done)
{
    Stroke settings = event.stroke;
    settings.samples.clear();
    document.beginStroke(settings, event.sources, event.stopAtPieces);
    for (const StrokeSample& sample : event.stroke.samples) done.stamps += document.extendStroke(sample).stamps;
    document.endStroke();
    ++done.strokes;
}

/// A piece edit, made at once as the window makes it in a job.
void replayPieceEdit(Document& document, const ScriptEvent& event)
{
    if (const auto* select = std::get_if<script::SelectPieceEvent>(&event)) {
        if (select->piece >= document.pieces().size())
            throw InputError("piece " + std::to_string(select->piece) + ": the document has " +
                             std::to_string(document.pieces().size()) + " pieces");
        return document.setActivePiece(select->piece);
    }
    if (const auto* looks = std::get_if<script::PieceLooksEvent>(&event))
        return document.setLooks(looks->looks, looks->label);
    if (std::holds_alternative<script::MovePieceEvent>(event) ||
        std::holds_alternative<script::ApplyPlacementEvent>(event)) {
        PieceMove move = moveOf(document, event);
        return document.movePiece(move.piece, move.placement, move.work({}), move.label, event);
    }
    PieceReplacement replacement = replacementOf(document, event);
    std::vector<DocumentPiece> added;
    for (Piece& piece : replacement.work({}))
        added.push_back(makeDocumentPiece(std::move(piece), {}, document.meshes()));
    document.replacePieces(replacement.replaced, std::move(added), replacement.label, event);
}

}  // namespace

void applyScriptEvent(Document& document, const ScriptEvent& event, const std::string& where, ReplayReport& done)
{
    try {
        if (const auto* stroke = std::get_if<script::StrokeEvent>(&event)) {
            replayStroke(document, *stroke, done);
        } else if (std::holds_alternative<script::UndoEvent>(event)) {
            if (!document.undo()) throw InputError("undo with nothing to undo");
            ++done.undos;
        } else if (std::holds_alternative<script::RedoEvent>(event)) {
            if (!document.redo()) throw InputError("redo with nothing to redo");
            ++done.redos;
        } else if (const auto* mask = std::get_if<script::MaskEvent>(&event)) {
            document.editMask(mask->operation, mask->times);
            ++done.maskOperations;
        } else if (const auto* selection = std::get_if<script::MaskSelectionEvent>(&event)) {
            FieldImage copy = document.session().field().deepCopy();
            applyMaskSelection(copy, selection->selection, nullptr);
            document.replaceMask(copy.maskPtr(), "mask " + std::string(maskSelectionName(selection->selection.kind)),
                                 event);
            ++done.maskOperations;
        } else if (const auto* drain = std::get_if<script::DrainEvent>(&event)) {
            document.drillHoles({drain->hole});
            ++done.drains;
        } else if (const auto* cut = std::get_if<script::CutEvent>(&event)) {
            FieldImage result = applyPrism(document.session().field(), cut->prism, cut->mode);
            refuseEmptyResult(result, "the model", prismModeName(cut->mode));
            document.replaceField(std::move(result), prismModeName(cut->mode), event);
            ++done.cuts;
        } else {
            replayPieceEdit(document, event);
            ++done.pieceEdits;
        }
    } catch (const InputError& e) {
        const std::string name = nameOf(event);
        throw InputError(where + (name.empty() ? "" : " (" + name + ")") + ": " + e.what(), e.remedy());
    }
}

ReplayReport replayScript(Document& document, const StrokeScript& script, const std::string& source,
                          const Progress& progress)
{
    ReplayReport done;
    for (std::size_t i = 0; i < script.events.size(); ++i) {
        applyScriptEvent(document, script.events[i], source + ": events[" + std::to_string(i) + "]", done);
        report(progress, double(i + 1) / double(script.events.size()));
    }
    return done;
}

}  // namespace sculpt
