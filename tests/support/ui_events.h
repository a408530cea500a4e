// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file ui_events.h
/// @brief The window's input as tests write it (an event recording for --play or a headless
///        SculptApp) and the reports its replay writes back, each found by its name.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sculpt::test {

/// An event recording being written, each event 20 ms after the previous one.
class UiEvents {
public:
    UiEvents& move(double x, double y);
    UiEvents& press(const std::string& button = "left", const std::vector<std::string>& mods = {});
    UiEvents& release(const std::string& button = "left");
    /// Press at (x0, y0), `steps` moves to (x1, y1), release.
    UiEvents& drag(double x0, double y0, double x1, double y1, int steps = 20,
                   const std::vector<std::string>& mods = {});
    UiEvents& key(const std::string& name, const std::vector<std::string>& mods = {});
    /// The wheel turned by `dy` notches (positive: away from the user).
    UiEvents& wheel(double dy);
    /// 40 moves once around the ellipse of centre (cx, cy) and radii rx, ry, from and back to
    /// its rightmost point: a lasso, with the button pressed there before.
    UiEvents& ellipse(double cx, double cy, double rx, double ry);
    UiEvents& text(const std::string& characters);
    /// The state appended to `path` as a JSON line called `name` (Reports finds it by that).
    UiEvents& report(const std::filesystem::path& path, const std::string& name);
    UiEvents& screenshot(const std::filesystem::path& path);
    UiEvents& resize(int width, int height);
    UiEvents& quit();
    UiEvents& wait(double seconds);
    /// The replay holds until the running job (a filter, a morph) has ended, or a morph's
    /// frames have played to the end.
    UiEvents& untilJobEnds();
    /// An internal error of `kind` (bad_alloc, openvdb, runtime) raised on the UI thread.
    UiEvents& fault(const std::string& kind);
    /// A file dropped on the window.
    UiEvents& drop(const std::filesystem::path& path);
    void write(const std::filesystem::path& path) const;

private:
    UiEvents& add(nlohmann::json event);
    nlohmann::json mEvents = nlohmann::json::array();
    double mTime = 0.0;
};

/// A report file's JSON lines, each found by the name the replay gave it.
class Reports {
public:
    /// @throws std::logic_error if two reports share a name.
    explicit Reports(const std::filesystem::path& path);
    /// The report called `name`. @throws std::out_of_range naming it if the replay wrote none.
    const nlohmann::json& operator[](const std::string& name) const;
    std::size_t size() const { return mLines.size(); }

private:
    std::filesystem::path mPath;
    std::map<std::string, nlohmann::json> mLines;
};

/// A reported piece's placed x: its placement's translation (row 3, OpenVDB's row vectors).
inline double placedX(const nlohmann::json& piece) { return piece["placement"][12].get<double>(); }

}  // namespace sculpt::test
