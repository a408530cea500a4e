// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/stroke_script.h"

#include "core/base/errors.h"
#include "core/base/json_fields.h"
#include "core/field/document_text.h"
#include "core/field/placement_check.h"
#include "core/primitives/scene_file.h"
#include "sculpt/session/sculpt_session.h"
#include "sculpt/session/shape_import.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace sculpt {

namespace {

using nlohmann::json;
using namespace json_fields;

constexpr const char* kFormat = "sculpt-strokes";
constexpr int kVersion = 1;

/// What parsing resolves paths against, and the targets read so far (strokes share them).
struct ParseContext {
    std::filesystem::path baseDir;
    std::map<std::string, std::shared_ptr<const FieldImage>> targets;
};

std::string describeEvent(size_t index, const json& event)
{
    std::string text = "events[" + std::to_string(index) + "]";
    if (event.is_object() && event.contains("tool") && event["tool"].is_string()) {
        text += " ('" + event["tool"].get<std::string>() + "' stroke)";
    }
    return text;
}

StrokeSample parseSample(const json& j, const std::string& where)
{
    StrokeSample s;
    if (j.is_array()) {
        s.positionWorld = vec3(j, where + ": field 'position'");
        return s;
    }
    onlyFields(j, {"position", "pressure", "view"}, where);
    s.positionWorld = vec3(field(j, "position", where), where + ": field 'position'");
    s.pressure = numberOr(j, "pressure", 1.0, where);
    if (j.contains("view")) s.viewDirection = vec3(j["view"], where + ": field 'view'");
    return s;
}

Symmetry parseSymmetry(const json& j, const std::string& where)
{
    Symmetry symmetry;
    if (!j.is_array()) throw InputError(where + ": field 'symmetry' must be an array of \"x\", \"y\", \"z\"");
    for (const json& axis : j) {
        const std::string name = axis.is_string() ? axis.get<std::string>() : axis.dump();
        if (name == "x") symmetry.x = true;
        else if (name == "y") symmetry.y = true;
        else if (name == "z") symmetry.z = true;
        else throw InputError(where + ": field 'symmetry' has \"" + name + "\" (expected \"x\", \"y\" or \"z\")");
    }
    return symmetry;
}

/// The primitive set of a primitive stroke: a scene file path (relative to the script) or inline.
std::shared_ptr<const PrimitiveStamp> parsePrimitives(const json& j, const std::string& where,
                                                      const std::filesystem::path& baseDir)
{
    const Scene scene = [&] {
        if (!j.is_string()) return parseScene(j.dump(), where + ": field 'primitives'");
        try {
            return readScene(baseDir / j.get<std::string>());
        } catch (const InputError& e) {
            throw InputError(where + ": field 'primitives': " + e.what(), e.remedy());
        }
    }();
    return std::make_shared<const PrimitiveStamp>(PrimitiveStamp{scene.primitives, scene.operation});
}

/// A follow stroke's target, read once per script.
std::shared_ptr<const FieldImage> parseTarget(const json& j, const std::string& where, ParseContext& context)
{
    if (!j.is_string()) throw InputError(where + ": field 'target' must be a file name");
    auto& target = context.targets[j.get<std::string>()];
    if (!target) {
        std::vector<std::string> warnings;  // a target's import warnings do not stop a replay
        try {
            target =
                std::make_shared<const FieldImage>(loadShape(context.baseDir / j.get<std::string>(), {}, warnings));
        } catch (const InputError& e) {
            throw InputError(where + ": field 'target': " + e.what(), e.remedy());
        }
    }
    return target;
}

/// The value field `key` names (`fallback` when absent), read by `fromName` (an enum's names);
/// an unknown name is reported with `where`.
template <typename FromName>
auto namedValue(const json& j, const char* key, const std::string& fallback, const std::string& where,
                FromName fromName)
{
    try {
        return fromName(textOr(j, key, fallback, where));
    } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
    }
}

Stroke parseStroke(const json& j, const std::string& where, ParseContext& context)
{
    onlyFields(j,
               {"tool", "radius", "strength", "falloff", "spacing", "symmetry", "keep_volume", "samples", "primitives",
                "target", "stop_at_pieces"},
               where);
    Stroke stroke;
    BrushSettings& brush = stroke.brush;
    brush.tool = namedValue(j, "tool", "", where, brushToolFromName);
    brush.falloff = namedValue(j, "falloff", falloffName(brush.falloff), where, falloffFromName);
    brush.radiusWorld = number(j, "radius", where);
    brush.strength = numberOr(j, "strength", brush.strength, where);
    brush.keepVolume = flagOr(j, "keep_volume", false, where);
    stroke.spacing = numberOr(j, "spacing", stroke.spacing, where);
    if (j.contains("symmetry")) stroke.symmetry = parseSymmetry(j["symmetry"], where);
    if (brush.tool == BrushTool::Primitive)
        brush.primitive = parsePrimitives(field(j, "primitives", where), where, context.baseDir);
    if (brush.tool == BrushTool::Follow) brush.target = parseTarget(field(j, "target", where), where, context);
    const json& samples = field(j, "samples", where);
    if (!samples.is_array()) throw InputError(where + ": field 'samples' must be an array");
    try {
        requireSampleCount(samples.size());
    } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
    }
    for (size_t i = 0; i < samples.size(); ++i) {
        stroke.samples.push_back(parseSample(samples[i], where + ": samples[" + std::to_string(i) + "]"));
    }
    try {
        validateStroke(stroke);
    } catch (const InputError& e) {
        throw InputError(where + ": " + e.what(), e.remedy());
    }
    return stroke;
}

/// A whole number from `least` to `most` in field `key`.
/// `value`, named `what` ("field 'times'"), as a whole number from `least` to `most`.
std::size_t wholeNumberOf(const json& value, const std::string& what, double least, double most,
                          const std::string& where)
{
    const double number = value.is_number() ? value.get<double>() : -1.0;
    if (!(number >= least && number <= most) || number != std::floor(number))
        throw InputError(where + ": " + what + " must be a whole number from " + std::to_string(int(least)) + " to " +
                         std::to_string(int(most)) + " (got " + value.dump() + ")");
    return std::size_t(number);
}

std::size_t wholeNumber(const json& j, const char* key, double least, double most, const std::string& where)
{
    return wholeNumberOf(field(j, key, where), std::string("field '") + key + "'", least, most, where);
}

ScriptEvent parseMaskEvent(const json& j, const std::string& where)
{
    onlyFields(j, {"action", "operation", "times"}, where);
    script::MaskEvent event;
    event.operation = namedValue(j, "operation", "", where, maskOperationFromName);
    event.times = j.contains("times") ? int(wholeNumber(j, "times", 1.0, 1000.0, where)) : 1;
    return event;
}

/// More polygon points than a hand draws in minutes: a file asking more is not a gesture.
constexpr std::size_t kMaxPolygonPoints = 100000;

/// The fields of a prism (a cut's, a mask selection's) read from `j`.
ViewPrism parsePrism(const json& j, const std::string& where)
{
    ViewPrism prism;
    const json& view = field(j, "view", where);
    if (!view.is_array() || view.size() != 16)
        throw InputError(where + ": field 'view' must be an array of 16 numbers");
    for (int k = 0; k < 16; ++k) {
        if (!view[std::size_t(k)].is_number()) throw InputError(where + ": field 'view' must hold numbers only");
        prism.viewFromWorld(k / 4, k % 4) = view[std::size_t(k)].get<double>();
    }
    prism.perspective = flagOr(j, "perspective", false, where);
    const json& polygon = field(j, "polygon", where);
    if (!polygon.is_array() || polygon.size() < 3 || polygon.size() > kMaxPolygonPoints)
        throw InputError(where + ": field 'polygon' must be an array of 3 to " + std::to_string(kMaxPolygonPoints) +
                         " points");
    for (const json& p : polygon) {
        if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
            throw InputError(where + ": field 'polygon' must hold points [x, y]");
        prism.polygon.emplace_back(p[0].get<double>(), p[1].get<double>());
    }
    prism.nearDepth = numberOr(j, "near", prism.nearDepth, where);
    prism.farDepth = numberOr(j, "far", prism.farDepth, where);
    if (j.contains("symmetry")) {
        const Symmetry s = parseSymmetry(j["symmetry"], where);
        prism.mirror = {s.x, s.y, s.z};
    }
    return prism;
}

ScriptEvent parseCutEvent(const json& j, const std::string& where)
{
    onlyFields(j, {"action", "mode", "view", "perspective", "polygon", "near", "far", "symmetry"}, where);
    script::CutEvent event;
    event.mode = namedValue(j, "mode", "cut", where, prismModeFromName);
    event.prism = parsePrism(j, where);
    return event;
}

ScriptEvent parseMaskSelection(const json& j, const std::string& where)
{
    script::MaskSelectionEvent event;
    MaskSelection& selection = event.selection;
    selection.kind = namedValue(j, "select", "", where, maskSelectionFromName);
    switch (selection.kind) {
    case MaskSelectionKind::Prism:
        onlyFields(j, {"action", "select", "erase", "view", "perspective", "polygon", "near", "far", "symmetry"},
                   where);
        selection.prism = parsePrism(j, where);
        break;
    case MaskSelectionKind::Cavity:
        onlyFields(j, {"action", "select", "erase", "crease_radius"}, where);
        selection.creaseRadiusWorld = number(j, "crease_radius", where);
        break;
    case MaskSelectionKind::Thin:
        onlyFields(j, {"action", "select", "erase", "thickness"}, where);
        selection.thicknessWorld = number(j, "thickness", where);
        break;
    case MaskSelectionKind::Island:
        onlyFields(j, {"action", "select", "erase", "point"}, where);
        selection.point = vec3(field(j, "point", where), where + ": field 'point'");
        break;
    }
    selection.erase = flagOr(j, "erase", false, where);
    return event;
}

ScriptEvent parseDrainEvent(const json& j, const std::string& where)
{
    onlyFields(j, {"action", "from", "to", "radius"}, where);
    script::DrainEvent event;
    event.hole.from = vec3(field(j, "from", where), where + ": field 'from'");
    event.hole.to = vec3(field(j, "to", where), where + ": field 'to'");
    event.hole.radiusWorld = number(j, "radius", where);
    return event;
}

// ---------------------------------------------------------------------------------------------
// The pieces' edits

/// More pieces than any document holds (a label map's at most): an index past it is no piece.
constexpr double kMaxPieceIndex = 100000.0;

std::size_t pieceIndex(const json& j, const char* key, const std::string& where)
{
    return wholeNumber(j, key, 0.0, kMaxPieceIndex, where);
}

/// A piece's placement: 16 numbers row by row (OpenVDB's row vectors), one placementProblem
/// accepts.
openvdb::Mat4d parsePlacement(const json& j, const std::string& where)
{
    if (!j.is_array() || j.size() != 16) throw InputError(where + ": field 'placement' must be an array of 16 numbers");
    openvdb::Mat4d m;
    for (int k = 0; k < 16; ++k) {
        const json& v = j[std::size_t(k)];
        if (!v.is_number() || !std::isfinite(v.get<double>()))
            throw InputError(where + ": field 'placement' must hold finite numbers only");
        m(k / 4, k % 4) = v.get<double>();
    }
    if (const std::string problem = placementProblem(m); !problem.empty())
        throw InputError(where + ": field 'placement' cannot place a piece: " + problem);
    return m;
}

json placementJson(const openvdb::Mat4d& m)
{
    json j = json::array();
    for (int k = 0; k < 16; ++k) j.push_back(m(k / 4, k % 4));
    return j;
}

PieceLook parseLook(const json& j, const std::string& where)
{
    onlyFields(j, {"name", "colour", "visible", "placement"}, where);
    PieceLook look;
    look.name = textOr(j, "name", "", where);
    if (const std::string problem = pieceNameProblem(look.name); !problem.empty())
        throw InputError(where + ": field 'name' cannot name a piece: " + problem);
    const openvdb::Vec3d colour = vec3(field(j, "colour", where), where + ": field 'colour'");
    for (int c = 0; c < 3; ++c) {
        if (!(colour[c] >= 0.0 && colour[c] <= 1.0))
            throw InputError(where + ": field 'colour' must hold numbers from 0 to 1");
        look.colour[c] = float(colour[c]);
    }
    look.visible = flagOr(j, "visible", true, where);
    look.placement = parsePlacement(field(j, "placement", where), where);
    return look;
}

ScriptEvent parsePieceEvent(const json& j, const std::string& where)
{
    const std::string edit = textOr(j, "edit", "", where);
    if (edit == "looks") {
        onlyFields(j, {"action", "edit", "looks", "label"}, where);
        const json& looks = field(j, "looks", where);
        if (!looks.is_array() || looks.empty() || looks.size() > std::size_t(kMaxPieceIndex))
            throw InputError(where + ": field 'looks' must be an array of one look per piece");
        script::PieceLooksEvent event;
        for (std::size_t i = 0; i < looks.size(); ++i)
            event.looks.push_back(parseLook(looks[i], where + ": looks[" + std::to_string(i) + "]"));
        event.label = textOr(j, "label", "piece looks", where);
        return event;
    }
    if (edit == "move") {
        onlyFields(j, {"action", "edit", "piece", "placement", "push"}, where);
        script::MovePieceEvent event{
            pieceIndex(j, "piece", where), parsePlacement(field(j, "placement", where), where), {}};
        if (j.contains("push")) {
            const json& pushed = j["push"];
            if (!pushed.is_array() || pushed.size() > std::size_t(kMaxPieceIndex))
                throw InputError(where + ": field 'push' must be an array of piece indices");
            for (std::size_t i = 0; i < pushed.size(); ++i)
                event.pushed.push_back(
                    wholeNumberOf(pushed[i], "field 'push[" + std::to_string(i) + "]'", 0.0, kMaxPieceIndex, where));
        }
        return event;
    }
    if (edit == "merge") {
        onlyFields(j, {"action", "edit", "piece", "with"}, where);
        return script::MergePiecesEvent{pieceIndex(j, "piece", where), pieceIndex(j, "with", where)};
    }
    onlyFields(j, {"action", "edit", "piece"}, where);
    const std::size_t piece = pieceIndex(j, "piece", where);
    if (edit == "select") return script::SelectPieceEvent{piece};
    if (edit == "apply_placement") return script::ApplyPlacementEvent{piece};
    if (edit == "duplicate") return script::DuplicatePieceEvent{piece};
    if (edit == "delete") return script::DeletePieceEvent{piece};
    if (edit == "split") return script::SplitPieceEvent{piece};
    throw InputError(where + ": field 'edit' is \"" + edit +
                     "\" (expected \"select\", \"looks\", \"move\", \"apply_placement\", \"duplicate\", "
                     "\"delete\", \"split\" or \"merge\")");
}

/// The prism's fields, added to `j`.
void addPrismJson(json& j, const ViewPrism& prism)
{
    json view = json::array(), polygon = json::array(), symmetry = json::array();
    for (int k = 0; k < 16; ++k) view.push_back(prism.viewFromWorld(k / 4, k % 4));
    for (const openvdb::Vec2d& p : prism.polygon) polygon.push_back({p.x(), p.y()});
    j["view"] = view;
    j["perspective"] = prism.perspective;
    j["polygon"] = polygon;
    if (std::isfinite(prism.nearDepth)) j["near"] = prism.nearDepth;
    if (std::isfinite(prism.farDepth)) j["far"] = prism.farDepth;
    for (int a = 0; a < 3; ++a)
        if (prism.mirror[std::size_t(a)]) symmetry.push_back(std::string(1, char('x' + a)));
    if (!symmetry.empty()) j["symmetry"] = symmetry;
}

json vec3Json(const openvdb::Vec3d& v) { return json::array({v.x(), v.y(), v.z()}); }

/// A piece event's JSON; nullopt for the events that are not a piece's.
json pieceEventJson(const ScriptEvent& event)
{
    const auto piece = [](const char* edit, std::size_t index) {
        return json{{"action", "piece"}, {"edit", edit}, {"piece", index}};
    };
    if (const auto* e = std::get_if<script::SelectPieceEvent>(&event)) return piece("select", e->piece);
    if (const auto* e = std::get_if<script::ApplyPlacementEvent>(&event)) return piece("apply_placement", e->piece);
    if (const auto* e = std::get_if<script::DuplicatePieceEvent>(&event)) return piece("duplicate", e->piece);
    if (const auto* e = std::get_if<script::DeletePieceEvent>(&event)) return piece("delete", e->piece);
    if (const auto* e = std::get_if<script::SplitPieceEvent>(&event)) return piece("split", e->piece);
    if (const auto* e = std::get_if<script::MergePiecesEvent>(&event)) {
        json j = piece("merge", e->piece);
        j["with"] = e->with;
        return j;
    }
    if (const auto* e = std::get_if<script::MovePieceEvent>(&event)) {
        json j = piece("move", e->piece);
        j["placement"] = placementJson(e->placement);
        if (!e->pushed.empty()) j["push"] = e->pushed;
        return j;
    }
    const auto& looks = std::get<script::PieceLooksEvent>(event);
    json all = json::array();
    for (const PieceLook& look : looks.looks) {
        all.push_back({{"name", look.name},
                       {"colour", {look.colour[0], look.colour[1], look.colour[2]}},
                       {"visible", look.visible},
                       {"placement", placementJson(look.placement)}});
    }
    return {{"action", "piece"}, {"edit", "looks"}, {"looks", std::move(all)}, {"label", looks.label}};
}

json maskSelectionJson(const MaskSelection& selection)
{
    json j = {{"action", "mask"}, {"select", maskSelectionName(selection.kind)}};
    if (selection.erase) j["erase"] = true;
    switch (selection.kind) {
    case MaskSelectionKind::Prism: addPrismJson(j, selection.prism); break;
    case MaskSelectionKind::Cavity: j["crease_radius"] = selection.creaseRadiusWorld; break;
    case MaskSelectionKind::Thin: j["thickness"] = selection.thicknessWorld; break;
    case MaskSelectionKind::Island: j["point"] = vec3Json(selection.point); break;
    }
    return j;
}

ScriptEvent parseEvent(const json& j, const std::string& where, ParseContext& context)
{
    if (!j.is_object()) throw InputError(where + " must be an object");
    if (j.contains("action")) {
        const std::string action = textOr(j, "action", "", where);
        if (action == "mask") return j.contains("select") ? parseMaskSelection(j, where) : parseMaskEvent(j, where);
        if (action == "cut") return parseCutEvent(j, where);
        if (action == "drain") return parseDrainEvent(j, where);
        if (action == "piece") return parsePieceEvent(j, where);
        onlyFields(j, {"action"}, where);
        if (action == "undo") return script::UndoEvent{};
        if (action == "redo") return script::RedoEvent{};
        throw InputError(where + ": field 'action' is \"" + action +
                         "\" (expected \"undo\", \"redo\", \"mask\", \"cut\", \"drain\" or \"piece\")");
    }
    field(j, "tool", where);
    script::StrokeEvent event{parseStroke(j, where, context), {}, flagOr(j, "stop_at_pieces", false, where)};
    if (j.contains("primitives") && j["primitives"].is_object()) event.sources.primitivesScene = j["primitives"].dump();
    if (event.stroke.brush.tool == BrushTool::Follow) event.sources.targetPath = j["target"].get<std::string>();
    return event;
}

json strokeJson(const script::StrokeEvent& event)
{
    const Stroke& stroke = event.stroke;
    json j = {{"tool", brushToolName(stroke.brush.tool)},
              {"radius", stroke.brush.radiusWorld},
              {"strength", stroke.brush.strength},
              {"falloff", falloffName(stroke.brush.falloff)},
              {"spacing", stroke.spacing}};
    if (stroke.brush.keepVolume) j["keep_volume"] = true;
    if (event.stopAtPieces) j["stop_at_pieces"] = true;
    json symmetry = json::array();
    if (stroke.symmetry.x) symmetry.push_back("x");
    if (stroke.symmetry.y) symmetry.push_back("y");
    if (stroke.symmetry.z) symmetry.push_back("z");
    if (!symmetry.empty()) j["symmetry"] = symmetry;
    if (stroke.brush.tool == BrushTool::Primitive) j["primitives"] = json::parse(event.sources.primitivesScene);
    if (stroke.brush.tool == BrushTool::Follow) j["target"] = event.sources.targetPath;
    json samples = json::array();
    for (const StrokeSample& s : stroke.samples) {
        samples.push_back(
            {{"position", vec3Json(s.positionWorld)}, {"pressure", s.pressure}, {"view", vec3Json(s.viewDirection)}});
    }
    j["samples"] = std::move(samples);
    return j;
}

}  // namespace

std::string writeStrokeScript(const StrokeScript& script)
{
    json events = json::array();
    for (const ScriptEvent& event : script.events) {
        if (const auto* stroke = std::get_if<script::StrokeEvent>(&event)) {
            events.push_back(strokeJson(*stroke));
        } else if (std::holds_alternative<script::UndoEvent>(event)) {
            events.push_back({{"action", "undo"}});
        } else if (std::holds_alternative<script::RedoEvent>(event)) {
            events.push_back({{"action", "redo"}});
        } else if (const auto* cut = std::get_if<script::CutEvent>(&event)) {
            json j = {{"action", "cut"}, {"mode", prismModeName(cut->mode)}};
            addPrismJson(j, cut->prism);
            events.push_back(std::move(j));
        } else if (const auto* selection = std::get_if<script::MaskSelectionEvent>(&event)) {
            events.push_back(maskSelectionJson(selection->selection));
        } else if (const auto* drain = std::get_if<script::DrainEvent>(&event)) {
            events.push_back({{"action", "drain"},
                              {"from", vec3Json(drain->hole.from)},
                              {"to", vec3Json(drain->hole.to)},
                              {"radius", drain->hole.radiusWorld}});
        } else if (const auto* mask = std::get_if<script::MaskEvent>(&event)) {
            events.push_back(
                {{"action", "mask"}, {"operation", maskOperationName(mask->operation)}, {"times", mask->times}});
        } else {
            events.push_back(pieceEventJson(event));
        }
    }
    return json{{"format", kFormat}, {"version", kVersion}, {"events", std::move(events)}}.dump(1) + "\n";
}

StrokeScript parseStrokeScript(const std::string& text, const std::string& source, const std::filesystem::path& baseDir)
{
    const json root = parse(text, source);
    if (!root.is_object()) throw InputError(source + ": a stroke script must be a JSON object");
    onlyFields(root, {"format", "version", "description", "events"}, source);
    if (textOr(root, "format", kFormat, source) != kFormat) {
        throw InputError(source + ": field 'format' must be \"" + std::string(kFormat) + "\"");
    }
    const double version = numberOr(root, "version", kVersion, source);
    if (version != kVersion) {
        throw InputError(source + ": version " + root["version"].dump() +
                         " is not supported (this program reads version " + std::to_string(kVersion) + ")");
    }
    const json& events = field(root, "events", source);
    if (!events.is_array()) throw InputError(source + ": field 'events' must be an array");
    StrokeScript script;
    ParseContext context{baseDir, {}};
    for (size_t i = 0; i < events.size(); ++i) {
        script.events.push_back(parseEvent(events[i], source + ": " + describeEvent(i, events[i]), context));
    }
    return script;
}

StrokeScript readStrokeScript(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the stroke script");
    std::ostringstream text;
    text << in.rdbuf();
    return parseStrokeScript(text.str(), path.string(), path.parent_path());
}

}  // namespace sculpt
