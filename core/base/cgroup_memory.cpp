// SPDX-License-Identifier: Apache-2.0
#include "core/base/cgroup_memory.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// v1 writes "no limit" as the largest page-aligned signed 64-bit number.
constexpr std::uint64_t kNoLimit = std::uint64_t(1) << 62;

/// The names of one hierarchy's files: v2's unified one, or v1's memory controller.
struct Hierarchy {
    const char* limit;
    const char* usage;
    const char* inactiveFile;  ///< the key in memory.stat
};
constexpr Hierarchy kUnified{"memory.max", "memory.current", "inactive_file"};
constexpr Hierarchy kMemoryV1{"memory.limit_in_bytes", "memory.usage_in_bytes", "total_inactive_file"};

/// A mount of a cgroup hierarchy: where it is mounted and which group is its root.
struct CgroupMount {
    fs::path mountPoint;
    std::string root;
};

std::optional<std::uint64_t> readNumber(const fs::path& file)
{
    std::ifstream in(file);
    std::uint64_t value = 0;
    if (in >> value) return value;
    return std::nullopt;  // missing, or "max"
}

std::uint64_t statValue(const fs::path& file, const std::string& key)
{
    std::ifstream in(file);
    std::string name;
    std::uint64_t value = 0;
    while (in >> name >> value)
        if (name == key) return value;
    return 0;
}

/// mountinfo writes a space in a path as \040 (octal escapes).
std::string unescapeOctal(const std::string& text)
{
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\\' && i + 3 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1]))) {
            out += char(std::stoi(text.substr(i + 1, 3), nullptr, 8));
            i += 3;
        } else {
            out += text[i];
        }
    }
    return out;
}

/// The mount of cgroup v2 (`v1Controller` empty) or of the v1 hierarchy holding that controller.
std::optional<CgroupMount> findMount(const std::string& mountinfo, const std::string& v1Controller)
{
    std::istringstream lines(mountinfo);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t dash = line.find(" - ");
        if (dash == std::string::npos) continue;
        std::istringstream before(line.substr(0, dash)), after(line.substr(dash + 3));
        std::string id, parent, device, root, mountPoint, type, source, options;
        before >> id >> parent >> device >> root >> mountPoint;
        after >> type >> source >> options;
        const bool wanted =
            v1Controller.empty()
                ? type == "cgroup2"
                : type == "cgroup" && ("," + options + ",").find("," + v1Controller + ",") != std::string::npos;
        if (wanted) return CgroupMount{unescapeOctal(mountPoint), unescapeOctal(root)};
    }
    return std::nullopt;
}

/// The group's path in the hierarchy: "0::PATH" for v2, "N:CONTROLLERS:PATH" for v1.
std::optional<std::string> groupPath(const std::string& procCgroup, const std::string& v1Controller)
{
    std::istringstream lines(procCgroup);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos) continue;
        const std::string controllers = line.substr(first + 1, second - first - 1);
        const bool wanted = v1Controller.empty()
                                ? line.substr(0, first) == "0" && controllers.empty()
                                : ("," + controllers + ",").find("," + v1Controller + ",") != std::string::npos;
        if (wanted) return line.substr(second + 1);
    }
    return std::nullopt;
}

/// A group's directory, or one above it, with its hierarchy's file names.
struct GroupLevel {
    fs::path dir;
    const Hierarchy* names;
};

/// The process's group directory in one hierarchy and every one above it up to the mount point
/// (none if the hierarchy is not mounted or the group is outside the mount).
void addLevels(const std::string& procCgroup, const std::string& mountinfo, const std::string& v1Controller,
               const Hierarchy& names, std::vector<GroupLevel>& levels)
{
    const std::optional<CgroupMount> mount = findMount(mountinfo, v1Controller);
    const std::optional<std::string> path = groupPath(procCgroup, v1Controller);
    if (!mount || !path) return;
    // A container sees its own group as the mount's root; a path outside the mount is not visible.
    const std::string root = mount->root == "/" ? "" : mount->root;
    if (path->compare(0, root.size(), root) != 0) return;
    const fs::path below = fs::path(path->substr(root.size())).relative_path();
    for (fs::path dir = below.empty() ? mount->mountPoint : mount->mountPoint / below;; dir = dir.parent_path()) {
        levels.push_back({dir, &names});
        if (dir == mount->mountPoint || !dir.has_relative_path()) break;
    }
}

std::vector<GroupLevel> groupLevels(const std::string& procCgroup, const std::string& mountinfo)
{
    std::vector<GroupLevel> levels;
    addLevels(procCgroup, mountinfo, "", kUnified, levels);
    addLevels(procCgroup, mountinfo, "memory", kMemoryV1, levels);
    return levels;
}

/// The least limit minus working set over `levels`.
std::optional<std::uint64_t> leftIn(const std::vector<GroupLevel>& levels)
{
    std::optional<std::uint64_t> least;
    for (const GroupLevel& level : levels) {
        const std::optional<std::uint64_t> limit = readNumber(level.dir / level.names->limit);
        if (!limit || *limit >= kNoLimit) continue;
        const std::uint64_t usage = readNumber(level.dir / level.names->usage).value_or(0);
        const std::uint64_t cache = std::min(usage, statValue(level.dir / "memory.stat", level.names->inactiveFile));
        const std::uint64_t workingSet = usage - cache;
        const std::uint64_t left = *limit > workingSet ? *limit - workingSet : 0;
        least = std::min(least.value_or(left), left);
    }
    return least;
}

std::string fileText(const char* path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

std::optional<std::uint64_t> cgroupMemoryLeft(const std::string& procCgroup, const std::string& mountinfo)
{
    return leftIn(groupLevels(procCgroup, mountinfo));
}

std::optional<std::uint64_t> cgroupMemoryLeft()
{
    // Where the groups are is found once: a process stays in its group (a batch job's does), and
    // the check runs before every large allocation, once per primitive of a scene being dragged.
    static const std::vector<GroupLevel> levels =
        groupLevels(fileText("/proc/self/cgroup"), fileText("/proc/self/mountinfo"));
    return leftIn(levels);
}

}  // namespace sculpt
