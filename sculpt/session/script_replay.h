// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file script_replay.h
/// @brief Replaying a stroke script's events on a document: the one path for `sculpt apply`, the
///        window's --strokes and the tests, each event one undo step of the document (and in its
///        own stroke log), as the window made it.

#include "core/base/progress.h"
#include "sculpt/session/stroke_script.h"

#include <string>

namespace sculpt {

class Document;

/// What a replay did.
struct ReplayReport {
    std::size_t strokes = 0, stamps = 0, undos = 0, redos = 0, maskOperations = 0, cuts = 0, drains = 0, pieceEdits = 0;
};

/// Applies `event` to `document`, counting it in `done`. @throws InputError naming `where` (the
/// event) and what is wrong: a brush larger than the model, undo with nothing to undo, a piece
/// the document does not have, a cut that leaves nothing.
void applyScriptEvent(Document& document, const ScriptEvent& event, const std::string& where, ReplayReport& done);

/// Applies the events in order, reporting progress per event; `source` names the script.
/// @throws InputError as applyScriptEvent, the document left as after the previous event.
ReplayReport replayScript(Document& document, const StrokeScript& script, const std::string& source,
                          const Progress& progress = {});

}  // namespace sculpt
