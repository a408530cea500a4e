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
///        {"action": "undo"}, {"action": "redo"}]}
/// A "mask" stroke paints the mask, "unmask" erases it; a "mask" action runs a mask operation
/// (mask_operations.h) over the whole mask, or masks a selection (mask_selection.h: "select" is
/// "prism" with the cut's "view", "perspective", "polygon", "near", "far", "symmetry"; "cavity"
/// with "crease_radius"; "thin" with "thickness"; "island" with "point"); a "drain" action drills
/// a drain hole (hollow.h); a "cut" action cuts (or fills) along the view with the
/// prism of a polygon (prism_cut.h: "view" is viewFromWorld row by row, OpenVDB's row-vector
/// convention; "near" and "far" are optional, all the way when absent).
/// A sample is an object or just its position. A follow stroke's target is a document, scan or
/// mesh (relative to the script), read at its own resolution (loadShape with no voxel size), as
/// the window reads it. Schema: data/strokes.schema.json; format: README.

#include "core/base/progress.h"
#include "core/solids/prism_cut.h"
#include "sculpt/session/sculpt_session.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// Where a stroke's extra inputs came from, as a script writes them.
struct StrokeSources {
    std::string primitivesScene;  ///< a primitive stroke's scene as JSON text, written inline
    std::string targetPath;       ///< a follow stroke's target file, as the script names it
};

struct ScriptEvent {
    enum class Kind { Stroke, Undo, Redo, Mask, Cut, MaskSelection, Drain };
    Kind kind = Kind::Stroke;
    Stroke stroke;  ///< Kind::Stroke only
    StrokeSources sources;
    MaskOperation maskOperation = MaskOperation::Invert;  ///< Kind::Mask only
    int maskTimes = 1;                                    ///< Kind::Mask only
    ViewPrism prism{};                                    ///< Kind::Cut only
    PrismMode prismMode = PrismMode::Cut;                 ///< Kind::Cut only
    MaskSelection maskSelection{};                        ///< Kind::MaskSelection only
    DrainHole hole{};                                     ///< Kind::Drain only
};

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

/// What a replay did.
struct ReplayReport {
    std::size_t strokes = 0, stamps = 0, undos = 0, redos = 0, maskOperations = 0, cuts = 0, drains = 0;
};

/// Applies the events in order, reporting progress per event.
/// @throws InputError naming the event (brush larger than the model, undo with nothing to undo),
///         with the session left as after the previous event.
ReplayReport replayScript(SculptSession& session, const StrokeScript& script, const std::string& source,
                          const Progress& progress = {});

}  // namespace sculpt
