// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file stroke_script.h
/// @brief Stroke scripts: a sculpting session recorded as JSON, replayed bit for bit.
///
///     {"format": "sculpt-strokes", "version": 1,
///      "events": [
///        {"tool": "add", "radius": 4, "strength": 1, "falloff": "smooth", "spacing": 0.25,
///         "symmetry": ["x"], "samples": [{"position": [1, 2, 3], "pressure": 0.8,
///                                        "view": [0, 0, -1]}, [4, 5, 6]]},
///        {"tool": "follow", "radius": 4, "target": "template.vdb", "samples": [[1, 2, 3]]},
///        {"tool": "mask", "radius": 4, "samples": [[1, 2, 3]]},
///        {"action": "mask", "operation": "invert", "times": 1},
///        {"action": "mask", "select": "cavity", "crease_radius": 2, "erase": false},
///        {"action": "cut", "mode": "cut", "view": [16 numbers], "perspective": true,
///         "polygon": [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1]], "near": 40, "far": 60,
///         "symmetry": ["x"]},
///        {"action": "drain", "from": [0, 0, -10], "to": [0, 0, -14], "radius": 1},
///        {"action": "piece", "edit": "move", "piece": 1, "placement": [16 numbers], "push": [0]},
///        {"action": "undo"}, {"action": "redo"}]}
/// A "mask" stroke paints the mask, "unmask" erases it; a "mask" action runs a mask operation
/// (mask_operations.h) over the whole mask, or masks a selection (mask_selection.h: "select" is
/// "prism" with the cut's "view", "perspective", "polygon", "near", "far", "symmetry"; "cavity"
/// with "crease_radius"; "thin" with "thickness"; "island" with "point"); a "drain" action drills
/// a drain hole (hollow.h); a "cut" action cuts (or fills) along the view with the
/// prism of a polygon (prism_cut.h: "view" is viewFromWorld row by row, OpenVDB's row-vector
/// convention; "near" and "far" are optional, all the way when absent).
/// A "piece" action edits the document's pieces, named by index: "select" (the piece later edits
/// change), "looks" (every piece's "name", "colour", "visible", "placement", and the step's
/// "label"), "move" ("placement", and "push": the pieces it dents aside), "apply_placement",
/// "duplicate", "delete", "split", "merge" ("with": the other piece). A stroke with
/// "stop_at_pieces" kept out of the other pieces shown. Replays: script_replay.h.
/// A sample is an object or just its position. A follow stroke's target is a document, scan or
/// mesh (relative to the script), read at its own resolution (loadShape with no voxel size), as
/// the window reads it. Schema: data/strokes.schema.json; format: README.

#include "sculpt/session/script_event.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

struct StrokeScript {
    std::vector<ScriptEvent> events;
};

/// Parses a script, reading the scenes and targets it names; `source` names it in messages and
/// `baseDir` resolves relative paths of primitive scenes and follow targets.
/// @throws InputError naming the source, the event ("events[3] ('add' stroke)") and the field.
StrokeScript parseStrokeScript(const std::string& text, const std::string& source,
                               const std::filesystem::path& baseDir);
/// Reads and parses a script file. @throws InputError as parseStrokeScript, or if unreadable.
StrokeScript readStrokeScript(const std::filesystem::path& path);

/// The script as JSON text that parseStrokeScript reads back to the same events, numbers exactly.
std::string writeStrokeScript(const StrokeScript& script);

}  // namespace sculpt
