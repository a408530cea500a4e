// SPDX-License-Identifier: Apache-2.0
#include "ui/input/input_event.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/json_fields.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <utility>

namespace sculpt::ui {

namespace {

using nlohmann::json;
using namespace json_fields;

constexpr const char* kFormat = "sculpt-ui-events";
constexpr int kVersion = 1;

const std::vector<std::pair<int, const char*>>& namedKeys()
{
    static const std::vector<std::pair<int, const char*>> keys = [] {
        std::vector<std::pair<int, const char*>> k = {
            {GLFW_KEY_SPACE, "Space"},
            {GLFW_KEY_ESCAPE, "Escape"},
            {GLFW_KEY_ENTER, "Enter"},
            {GLFW_KEY_KP_ENTER, "KPEnter"},
            {GLFW_KEY_TAB, "Tab"},
            {GLFW_KEY_BACKSPACE, "Backspace"},
            {GLFW_KEY_DELETE, "Delete"},
            {GLFW_KEY_LEFT, "Left"},
            {GLFW_KEY_RIGHT, "Right"},
            {GLFW_KEY_UP, "Up"},
            {GLFW_KEY_DOWN, "Down"},
            {GLFW_KEY_HOME, "Home"},
            {GLFW_KEY_END, "End"},
            {GLFW_KEY_PAGE_UP, "PageUp"},
            {GLFW_KEY_PAGE_DOWN, "PageDown"},
            {GLFW_KEY_LEFT_BRACKET, "LeftBracket"},
            {GLFW_KEY_RIGHT_BRACKET, "RightBracket"},
            {GLFW_KEY_KP_DECIMAL, "KPDecimal"},
            {GLFW_KEY_KP_ADD, "KPAdd"},
            {GLFW_KEY_KP_SUBTRACT, "KPSubtract"},
            {GLFW_KEY_LEFT_SHIFT, "LeftShift"},
            {GLFW_KEY_LEFT_CONTROL, "LeftControl"},
            {GLFW_KEY_LEFT_ALT, "LeftAlt"},
            {GLFW_KEY_RIGHT_SHIFT, "RightShift"},
            {GLFW_KEY_RIGHT_CONTROL, "RightControl"},
            {GLFW_KEY_RIGHT_ALT, "RightAlt"},
            {GLFW_KEY_EQUAL, "Equal"},
            {GLFW_KEY_MINUS, "Minus"},
            {GLFW_KEY_PERIOD, "Period"},
        };
        static const char* letters[] = {"A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M",
                                        "N", "O", "P", "Q", "R", "S", "T", "U", "V", "W", "X", "Y", "Z"};
        for (int i = 0; i < 26; ++i) k.emplace_back(GLFW_KEY_A + i, letters[i]);
        static const char* digits[] = {"0", "1", "2", "3", "4", "5", "6", "7", "8", "9"};
        static const char* pad[] = {"KP0", "KP1", "KP2", "KP3", "KP4", "KP5", "KP6", "KP7", "KP8", "KP9"};
        for (int i = 0; i < 10; ++i) {
            k.emplace_back(GLFW_KEY_0 + i, digits[i]);
            k.emplace_back(GLFW_KEY_KP_0 + i, pad[i]);
        }
        static const char* functions[] = {"F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8", "F9", "F10", "F11", "F12"};
        for (int i = 0; i < 12; ++i) k.emplace_back(GLFW_KEY_F1 + i, functions[i]);
        return k;
    }();
    return keys;
}

const std::vector<std::pair<EventType, const char*>> kTypeNames = {
    {EventType::MouseMove, "move"},
    {EventType::MouseButton, "button"},
    {EventType::Wheel, "wheel"},
    {EventType::Key, "key"},
    {EventType::Text, "text"},
    {EventType::Resize, "resize"},
    {EventType::Screenshot, "screenshot"},
    {EventType::Report, "report"},
    {EventType::Quit, "quit"},
    {EventType::WaitForJob, "wait"},
    {EventType::Fault, "fault"},
    {EventType::Drop, "drop"},
};
const std::vector<std::pair<int, const char*>> kModNames = {
    {kShift, "shift"}, {kControl, "ctrl"}, {kAlt, "alt"}, {kSuper, "super"}};
const char* kButtonNames[] = {"left", "right", "middle"};

int parseMods(const json& j, const std::string& where)
{
    if (!j.contains("mods")) return 0;
    if (!j["mods"].is_array())
        throw InputError(where + ": field 'mods' must be an array of \"shift\", \"ctrl\", \"alt\", \"super\"");
    int mods = 0;
    for (const json& m : j["mods"]) {
        bool known = false;
        for (const auto& [bit, name] : kModNames) {
            if (m.is_string() && m.get<std::string>() == name) mods |= bit, known = true;
        }
        if (!known)
            throw InputError(where + ": field 'mods' has " + m.dump() +
                             " (expected \"shift\", \"ctrl\", \"alt\" or \"super\")");
    }
    return mods;
}

bool parsePress(const json& j, const std::string& where)
{
    const std::string action = textOr(j, "action", "press", where);
    if (action != "press" && action != "release") {
        throw InputError(where + ": field 'action' is \"" + action + "\" (expected \"press\" or \"release\")");
    }
    return action == "press";
}

/// One event of the file; a key or button without "action" is a tap: press then release.
void parseEvent(const json& j, const std::string& where, double& clock, std::vector<InputEvent>& out)
{
    if (!j.is_object()) throw InputError(where + " must be an object");
    InputEvent e;
    const std::string type = textOr(j, "type", "", where);
    bool known = false;
    for (const auto& [t, name] : kTypeNames) {
        if (type == name) e.type = t, known = true;
    }
    if (!known)
        throw InputError(
            where + ": field 'type' is \"" + type +
            "\" (expected move, button, wheel, key, text, resize, screenshot, report, quit, wait, fault or "
            "drop)");
    if (j.contains("t")) {
        const double t = number(j, "t", where);
        if (!(t >= clock)) throw InputError(where + ": field 't' must not decrease (seconds since the start)");
        clock = t;
    }
    e.time = clock;
    bool tap = false;
    switch (e.type) {
    case EventType::MouseMove:
        e.x = number(j, "x", where);
        e.y = number(j, "y", where);
        break;
    case EventType::Wheel:
        e.x = numberOr(j, "dx", 0.0, where);
        e.y = numberOr(j, "dy", 0.0, where);
        break;
    case EventType::MouseButton: {
        const std::string button = textOr(j, "button", "left", where);
        e.button = button == "left"     ? kLeftButton
                   : button == "right"  ? kRightButton
                   : button == "middle" ? kMiddleButton
                                        : -1;
        if (e.button < 0)
            throw InputError(where + ": field 'button' is \"" + button + "\" (expected left, right or middle)");
        e.mods = parseMods(j, where);
        tap = !j.contains("action");
        e.press = parsePress(j, where);
        break;
    }
    case EventType::Key: {
        const std::string key = textOr(j, "key", "", where);
        e.key = keyFromName(key);
        if (e.key < 0)
            throw InputError(where + ": field 'key' is \"" + key +
                             "\", not a key name (A-Z, 0-9, F1-F12, Escape, Enter, ...)");
        e.mods = parseMods(j, where);
        tap = !j.contains("action");
        e.press = parsePress(j, where);
        break;
    }
    case EventType::Text: e.text = textOr(j, "text", "", where); break;
    case EventType::Resize:
        e.width = int(number(j, "width", where));
        e.height = int(number(j, "height", where));
        if (e.width < 64 || e.height < 64 || e.width > 8192 || e.height > 8192) {
            throw InputError(where + ": a window must be 64 to 8192 pixels wide and high");
        }
        break;
    case EventType::Screenshot:
    case EventType::Report:
    case EventType::Drop:
        e.text = textOr(j, "path", "", where);
        if (e.text.empty()) throw InputError(where + ": field 'path' is missing");
        if (e.type == EventType::Report) e.name = textOr(j, "name", "", where);
        break;
    case EventType::Fault:
        e.text = textOr(j, "kind", "", where);
        if (std::find(std::begin(kFaultKinds), std::end(kFaultKinds), e.text) == std::end(kFaultKinds))
            throw InputError(where + ": field 'kind' is \"" + e.text + "\" (expected bad_alloc, openvdb or runtime)");
        break;
    case EventType::Quit:
    case EventType::WaitForJob: break;
    }
    out.push_back(e);
    if (tap) {
        e.press = false;
        out.push_back(e);
    }
}

json eventJson(const InputEvent& e)
{
    json j = {{"t", e.time}};
    for (const auto& [t, name] : kTypeNames) {
        if (t == e.type) j["type"] = name;
    }
    json mods = json::array();
    for (const auto& [bit, name] : kModNames) {
        if (e.mods & bit) mods.push_back(name);
    }
    switch (e.type) {
    case EventType::MouseMove: j["x"] = e.x, j["y"] = e.y; break;
    case EventType::Wheel: j["dx"] = e.x, j["dy"] = e.y; break;
    case EventType::MouseButton:
        j["button"] = kButtonNames[e.button], j["action"] = e.press ? "press" : "release", j["mods"] = mods;
        break;
    case EventType::Key:
        j["key"] = keyName(e.key), j["action"] = e.press ? "press" : "release", j["mods"] = mods;
        break;
    case EventType::Text: j["text"] = e.text; break;
    case EventType::Resize: j["width"] = e.width, j["height"] = e.height; break;
    case EventType::Screenshot:
    case EventType::Drop: j["path"] = e.text; break;
    case EventType::Report:
        j["path"] = e.text;
        if (!e.name.empty()) j["name"] = e.name;
        break;
    case EventType::Fault: j["kind"] = e.text; break;
    case EventType::Quit:
    case EventType::WaitForJob: break;
    }
    return j;
}

}  // namespace

int modifierOfKey(int key)
{
    switch (key) {
    case GLFW_KEY_LEFT_SHIFT:
    case GLFW_KEY_RIGHT_SHIFT: return kShift;
    case GLFW_KEY_LEFT_CONTROL:
    case GLFW_KEY_RIGHT_CONTROL: return kControl;
    case GLFW_KEY_LEFT_ALT:
    case GLFW_KEY_RIGHT_ALT: return kAlt;
    default: return 0;
    }
}

std::string keyName(int key)
{
    for (const auto& [code, name] : namedKeys()) {
        if (code == key) return name;
    }
    return "";
}

int keyFromName(const std::string& name)
{
    for (const auto& [code, known] : namedKeys()) {
        if (name == known) return code;
    }
    return -1;
}

std::vector<InputEvent> readInputEvents(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot read the event recording");
    std::ostringstream text;
    text << in.rdbuf();
    const json root = parse(text.str(), path);
    if (!root.is_object()) throw InputError(path + ": an event recording must be a JSON object");
    onlyFields(root, {"format", "version", "description", "events"}, path);
    if (textOr(root, "format", kFormat, path) != kFormat) {
        throw InputError(path + ": field 'format' must be \"" + std::string(kFormat) + "\"");
    }
    if (numberOr(root, "version", kVersion, path) != kVersion) {
        throw InputError(path + ": version " + root["version"].dump() +
                         " is not supported (this program reads version 1)");
    }
    const json& events = field(root, "events", path);
    if (!events.is_array()) throw InputError(path + ": field 'events' must be an array");
    std::vector<InputEvent> out;
    double clock = 0.0;
    for (size_t i = 0; i < events.size(); ++i) {
        parseEvent(events[i], path + ": events[" + std::to_string(i) + "]", clock, out);
    }
    return out;
}

void writeInputEvents(const std::vector<InputEvent>& events, const std::string& path)
{
    json list = json::array();
    for (const InputEvent& e : events) list.push_back(eventJson(e));
    const std::string text = json{{"format", kFormat}, {"version", kVersion}, {"events", list}}.dump(1) + "\n";
    writeFileAtomically(path, text);
}

}  // namespace sculpt::ui
