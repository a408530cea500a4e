// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file input_event.h
/// @brief One thing the user did, as the window reported it: the unit of live input, of
///        recordings (--record) and of replays (--play).
///
/// Live GLFW callbacks and replayed files produce the same events, which go through the same
/// code, so a replay is a faithful test of the UI. Coordinates are window pixels, origin top
/// left. The file format is data/ui-events.schema.json.

#include <string>
#include <vector>

namespace sculpt::ui {

enum class EventType {
    MouseMove,    ///< x, y
    MouseButton,  ///< button, press, mods
    Wheel,        ///< x, y: scroll offsets (y > 0: away from the user)
    Key,          ///< key (GLFW key code), press, mods
    Text,         ///< text: characters typed (UTF-8)
    Resize,       ///< width, height
    Screenshot,   ///< path: the composed frame as PNG, after this event's frame
    Report,       ///< path, name: the state (checksum, pick, uploads, ...) appended as a JSON line
    Quit,         ///< as closing the window
    WaitForJob,   ///< the replay holds until the running job has ended (or a morph's playback)
    Fault,        ///< text: an internal error to raise on the UI thread (tests of the recovery)
    Drop,         ///< text: the path of a file dropped on the window
};

/// The internal errors a fault event may raise: out of memory, an OpenVDB error, any other.
inline constexpr const char* kFaultKinds[] = {"bad_alloc", "openvdb", "runtime"};

/// GLFW's modifier bits (GLFW_MOD_SHIFT, ...), repeated so this header needs no GLFW.
enum Modifier : int { kShift = 0x1, kControl = 0x2, kAlt = 0x4, kSuper = 0x8 };

enum MouseButtonId : int { kLeftButton = 0, kRightButton = 1, kMiddleButton = 2 };

struct InputEvent {
    EventType type = EventType::MouseMove;
    double time = 0.0;  ///< seconds since the program started (recorded; replays pace by it)
    double x = 0.0, y = 0.0;
    int button = kLeftButton;
    bool press = true;
    int key = 0;
    int mods = 0;
    std::string text;  ///< Text: the characters; Screenshot, Report, Drop: the path
    std::string name;  ///< Report: what the report is called (tests find it by its name), or ""
    int width = 0, height = 0;
};

/// Reads a recording. @throws InputError naming the file, the event and the field.
std::vector<InputEvent> readInputEvents(const std::string& path);
/// Writes a recording (atomically). @throws InputError naming the file.
void writeInputEvents(const std::vector<InputEvent>& events, const std::string& path);

/// The Modifier bit a modifier key (Left/Right Shift, Control, Alt) sets; 0 for other keys.
int modifierOfKey(int key);

/// "A", "Escape", "LeftBracket", "KP1", ... for a GLFW key code; "" if it has no name here.
std::string keyName(int key);
/// The GLFW key code of a name keyName gives; -1 if unknown.
int keyFromName(const std::string& name);

}  // namespace sculpt::ui
