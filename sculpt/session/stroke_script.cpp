#include "sculpt/session/stroke_script.h"

#include "core/base/errors.h"
#include "core/base/json_fields.h"
#include "core/field/csg_combine.h"
#include "core/primitives/scene_file.h"
#include "sculpt/session/model_filter.h"
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
                "target"},
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

ScriptEvent parseMaskEvent(const json& j, const std::string& where)
{
    onlyFields(j, {"action", "operation", "times"}, where);
    ScriptEvent event;
    event.kind = ScriptEvent::Kind::Mask;
    event.maskOperation = namedValue(j, "operation", "", where, maskOperationFromName);
    const double times = numberOr(j, "times", 1.0, where);
    if (!(times >= 1.0 && times <= 1000.0) || times != std::floor(times))
        throw InputError(where + ": field 'times' must be a whole number from 1 to 1000 (got " + j["times"].dump() +
                         ")");
    event.maskTimes = int(times);
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
    ScriptEvent event;
    event.kind = ScriptEvent::Kind::Cut;
    event.prismMode = namedValue(j, "mode", "cut", where, prismModeFromName);
    event.prism = parsePrism(j, where);
    return event;
}

ScriptEvent parseMaskSelection(const json& j, const std::string& where)
{
    ScriptEvent event;
    event.kind = ScriptEvent::Kind::MaskSelection;
    MaskSelection& selection = event.maskSelection;
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
    ScriptEvent event;
    event.kind = ScriptEvent::Kind::Drain;
    event.hole.from = vec3(field(j, "from", where), where + ": field 'from'");
    event.hole.to = vec3(field(j, "to", where), where + ": field 'to'");
    event.hole.radiusWorld = number(j, "radius", where);
    return event;
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
        onlyFields(j, {"action"}, where);
        if (action == "undo") return {ScriptEvent::Kind::Undo, {}, {}};
        if (action == "redo") return {ScriptEvent::Kind::Redo, {}, {}};
        throw InputError(where + ": field 'action' is \"" + action +
                         "\" (expected \"undo\", \"redo\", \"mask\", \"cut\" or \"drain\")");
    }
    field(j, "tool", where);
    ScriptEvent event{ScriptEvent::Kind::Stroke, parseStroke(j, where, context), {}};
    if (j.contains("primitives") && j["primitives"].is_object()) event.sources.primitivesScene = j["primitives"].dump();
    if (event.stroke.brush.tool == BrushTool::Follow) event.sources.targetPath = j["target"].get<std::string>();
    return event;
}

json strokeJson(const ScriptEvent& event)
{
    const Stroke& stroke = event.stroke;
    json j = {{"tool", brushToolName(stroke.brush.tool)},
              {"radius", stroke.brush.radiusWorld},
              {"strength", stroke.brush.strength},
              {"falloff", falloffName(stroke.brush.falloff)},
              {"spacing", stroke.spacing}};
    if (stroke.brush.keepVolume) j["keep_volume"] = true;
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
        switch (event.kind) {
        case ScriptEvent::Kind::Stroke: events.push_back(strokeJson(event)); break;
        case ScriptEvent::Kind::Undo: events.push_back({{"action", "undo"}}); break;
        case ScriptEvent::Kind::Redo: events.push_back({{"action", "redo"}}); break;
        case ScriptEvent::Kind::Cut: {
            json cut = {{"action", "cut"}, {"mode", prismModeName(event.prismMode)}};
            addPrismJson(cut, event.prism);
            events.push_back(std::move(cut));
            break;
        }
        case ScriptEvent::Kind::MaskSelection: events.push_back(maskSelectionJson(event.maskSelection)); break;
        case ScriptEvent::Kind::Drain:
            events.push_back({{"action", "drain"},
                              {"from", vec3Json(event.hole.from)},
                              {"to", vec3Json(event.hole.to)},
                              {"radius", event.hole.radiusWorld}});
            break;
        case ScriptEvent::Kind::Mask:
            events.push_back({{"action", "mask"},
                              {"operation", maskOperationName(event.maskOperation)},
                              {"times", event.maskTimes}});
            break;
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

ReplayReport replayScript(SculptSession& session, const StrokeScript& script, const std::string& source,
                          const Progress& progress)
{
    ReplayReport done;
    for (size_t i = 0; i < script.events.size(); ++i) {
        const ScriptEvent& event = script.events[i];
        const std::string where = source + ": events[" + std::to_string(i) + "]";
        switch (event.kind) {
        case ScriptEvent::Kind::Stroke: try { done.stamps += session.applyStroke(event.stroke).stamps;
            } catch (const InputError& e) {
                throw InputError(where + " ('" + brushToolName(event.stroke.brush.tool) + "' stroke): " + e.what(),
                                 e.remedy());
            }
            ++done.strokes;
            break;
        case ScriptEvent::Kind::Undo:
            if (!session.undo()) throw InputError(where + ": undo with nothing to undo");
            ++done.undos;
            break;
        case ScriptEvent::Kind::Redo:
            if (!session.redo()) throw InputError(where + ": redo with nothing to redo");
            ++done.redos;
            break;
        case ScriptEvent::Kind::Mask:
            session.editMask(event.maskOperation, event.maskTimes);
            ++done.maskOperations;
            break;
        case ScriptEvent::Kind::MaskSelection: try { session.selectMask(event.maskSelection);
            } catch (const InputError& e) {
                throw InputError(where + " (mask " + maskSelectionName(event.maskSelection.kind) + "): " + e.what(),
                                 e.remedy());
            }
            ++done.maskOperations;
            break;
        case ScriptEvent::Kind::Drain: try { session.drillHoles({event.hole});
            } catch (const InputError& e) {
                throw InputError(where + " (drain): " + e.what(), e.remedy());
            }
            ++done.drains;
            break;
        case ScriptEvent::Kind::Cut:
            try {
                FieldImage result = applyPrism(session.field(), event.prism, event.prismMode);
                refuseEmptyResult(result, source, prismModeName(event.prismMode));
                session.replaceField(std::move(result));
            } catch (const InputError& e) {
                throw InputError(where + " (" + prismModeName(event.prismMode) + "): " + e.what(), e.remedy());
            }
            ++done.cuts;
            break;
        }
        report(progress, double(i + 1) / double(script.events.size()));
    }
    return done;
}

}  // namespace sculpt
