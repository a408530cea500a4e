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

/// The least limit minus working set from the group's directory up to the mount point.
std::optional<std::uint64_t> leftInHierarchy(const std::string& procCgroup, const std::string& mountinfo,
                                             const std::string& v1Controller, const Hierarchy& names)
{
    const std::optional<CgroupMount> mount = findMount(mountinfo, v1Controller);
    const std::optional<std::string> path = groupPath(procCgroup, v1Controller);
    if (!mount || !path) return std::nullopt;
    // A container sees its own group as the mount's root; a path outside the mount is not visible.
    const std::string root = mount->root == "/" ? "" : mount->root;
    if (path->compare(0, root.size(), root) != 0) return std::nullopt;
    const fs::path below = fs::path(path->substr(root.size())).relative_path();
    fs::path dir = below.empty() ? mount->mountPoint : mount->mountPoint / below;
    std::optional<std::uint64_t> least;
    for (;; dir = dir.parent_path()) {
        const std::optional<std::uint64_t> limit = readNumber(dir / names.limit);
        if (limit && *limit < kNoLimit) {
            const std::uint64_t usage = readNumber(dir / names.usage).value_or(0);
            const std::uint64_t cache = std::min(usage, statValue(dir / "memory.stat", names.inactiveFile));
            const std::uint64_t workingSet = usage - cache;
            const std::uint64_t left = *limit > workingSet ? *limit - workingSet : 0;
            least = std::min(least.value_or(left), left);
        }
        if (dir == mount->mountPoint || !dir.has_relative_path()) break;
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
    const std::optional<std::uint64_t> unified = leftInHierarchy(procCgroup, mountinfo, "", kUnified);
    const std::optional<std::uint64_t> v1 = leftInHierarchy(procCgroup, mountinfo, "memory", kMemoryV1);
    if (unified && v1) return std::min(*unified, *v1);
    return unified ? unified : v1;
}

std::optional<std::uint64_t> cgroupMemoryLeft()
{
    return cgroupMemoryLeft(fileText("/proc/self/cgroup"), fileText("/proc/self/mountinfo"));
}

}  // namespace sculpt
