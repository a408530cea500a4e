#pragma once
/// @file ui_driver.h
/// @brief Drives the real sculpt-ui under Xvfb for tests: builds an event recording, replays it
///        (--play), and reads back the reports and screenshots it wrote.

#include "tests/support/run_sculpt.h"

#include <nlohmann/json.hpp>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

class vtkImageData;

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
    void write(const std::filesystem::path& path) const;

private:
    UiEvents& add(nlohmann::json event);
    nlohmann::json mEvents = nlohmann::json::array();
    double mTime = 0.0;
};

/// `xvfb-run -a sculpt-ui ARGS` in `workDir` (a 1280x800 screen).
CommandResult runUi(const std::string& args, const std::string& workDir);
/// The command line of that, for running it in the background.
std::string uiCommand(const std::string& args);

/// sculpt-ui started in the background (uiCommand) in a process group of its own: the test keeps
/// that group's id, and the destructor kills what is left of it, so an ASSERT that returns early
/// leaves no window or X server running. Nothing is ever looked up by name.
class BackgroundUi {
public:
    BackgroundUi(const std::string& args, const std::filesystem::path& workDir);
    ~BackgroundUi();
    BackgroundUi(const BackgroundUi&) = delete;
    BackgroundUi& operator=(const BackgroundUi&) = delete;

    /// Kills the program alone with SIGKILL, as a crash would end it (xvfb-run then stops its X
    /// server). @return false if the group holds no sculpt-ui.
    bool killProgram();

private:
    int mGroup = -1;  // the process group's id: the pid of the shell started first in it
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

vtkSmartPointer<vtkImageData> readPng(const std::filesystem::path& path);
/// Share of pixels whose RGB differ by more than 8 in some channel.
double differingShare(vtkImageData* a, vtkImageData* b);

}  // namespace sculpt::test
