// SPDX-License-Identifier: Apache-2.0
#include "tests/support/ui_events.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace sculpt::test {

UiEvents& UiEvents::add(nlohmann::json event)
{
    mTime += 0.02;
    event["t"] = mTime;
    mEvents.push_back(std::move(event));
    return *this;
}

UiEvents& UiEvents::move(double x, double y) { return add({{"type", "move"}, {"x", x}, {"y", y}}); }

UiEvents& UiEvents::press(const std::string& button, const std::vector<std::string>& mods)
{
    return add({{"type", "button"}, {"button", button}, {"action", "press"}, {"mods", mods}});
}

UiEvents& UiEvents::wheel(double dy) { return add({{"type", "wheel"}, {"dy", dy}}); }

UiEvents& UiEvents::release(const std::string& button)
{
    return add({{"type", "button"}, {"button", button}, {"action", "release"}});
}

UiEvents& UiEvents::drag(double x0, double y0, double x1, double y1, int steps, const std::vector<std::string>& mods)
{
    move(x0, y0);
    press("left", mods);
    for (int i = 1; i <= steps; ++i) move(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps);
    return release("left");
}

UiEvents& UiEvents::key(const std::string& name, const std::vector<std::string>& mods)
{
    return add({{"type", "key"}, {"key", name}, {"mods", mods}});
}

UiEvents& UiEvents::ellipse(double cx, double cy, double rx, double ry)
{
    for (int i = 1; i <= 40; ++i) {
        const double a = 2.0 * M_PI * i / 40;
        move(cx + rx * std::cos(a), cy + ry * std::sin(a));
    }
    return *this;
}

UiEvents& UiEvents::text(const std::string& characters) { return add({{"type", "text"}, {"text", characters}}); }
UiEvents& UiEvents::report(const std::filesystem::path& path, const std::string& name)
{
    return add({{"type", "report"}, {"path", path.string()}, {"name", name}});
}
UiEvents& UiEvents::screenshot(const std::filesystem::path& path)
{
    return add({{"type", "screenshot"}, {"path", path.string()}});
}
UiEvents& UiEvents::resize(int width, int height)
{
    return add({{"type", "resize"}, {"width", width}, {"height", height}});
}

UiEvents& UiEvents::quit() { return add({{"type", "quit"}}); }

UiEvents& UiEvents::untilJobEnds() { return add({{"type", "wait"}}); }

UiEvents& UiEvents::fault(const std::string& kind) { return add({{"type", "fault"}, {"kind", kind}}); }
UiEvents& UiEvents::drop(const std::filesystem::path& path) { return add({{"type", "drop"}, {"path", path.string()}}); }

UiEvents& UiEvents::wait(double seconds)
{
    mTime += seconds;
    return *this;
}

void UiEvents::write(const std::filesystem::path& path) const
{
    std::ofstream(path) << nlohmann::json{{"format", "sculpt-ui-events"}, {"version", 1}, {"events", mEvents}}.dump(1);
}

Reports::Reports(const std::filesystem::path& path) : mPath(path)
{
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        nlohmann::json report = nlohmann::json::parse(line);
        const std::string name = report.value("name", std::string());
        if (!mLines.emplace(name, std::move(report)).second)
            throw std::logic_error(path.string() + ": two reports are called \"" + name + "\"");
    }
}

const nlohmann::json& Reports::operator[](const std::string& name) const
{
    const auto it = mLines.find(name);
    if (it == mLines.end()) throw std::out_of_range(mPath.string() + ": the replay wrote no report \"" + name + "\"");
    return it->second;
}

}  // namespace sculpt::test
