// SPDX-License-Identifier: Apache-2.0
#include "core/base/memory_budget.h"

#include "core/base/cgroup_memory.h"
#include "core/base/errors.h"
#include "core/base/text_format.h"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <optional>

namespace sculpt {

namespace {

std::uint64_t freeMemoryBytes()
{
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit) {
        if (key == "MemAvailable:") return kib * 1024;
    }
    return std::uint64_t(sysconf(_SC_PHYS_PAGES)) * std::uint64_t(sysconf(_SC_PAGE_SIZE));
}

std::optional<std::uint64_t> addressSpaceLeft()
{
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    const std::uint64_t used = addressSpaceBytes();
    return limit.rlim_cur > used ? limit.rlim_cur - used : 0;
}

}  // namespace

std::uint64_t addressSpaceBytes()
{
    std::ifstream statm("/proc/self/statm");
    std::uint64_t pages = 0;
    statm >> pages;
    return pages * std::uint64_t(sysconf(_SC_PAGESIZE));
}

MemoryLimit memoryLimit()
{
    MemoryLimit least{freeMemoryBytes(), ""};
    if (const auto left = cgroupMemoryLeft(); left && *left < least.bytes)
        least = {*left, "the control group's memory limit"};
    if (const auto left = addressSpaceLeft(); left && *left < least.bytes)
        least = {*left, "the address-space limit, ulimit -v"};
    return least;
}

std::uint64_t availableMemoryBytes() { return memoryLimit().bytes; }

void requireMemory(double bytes, const std::string& what)
{
    const MemoryLimit limit = memoryLimit();
    if (!(bytes <= double(limit.bytes))) {
        throw InputError(what + " needs about " + formatBytes(bytes) + " of memory but only " +
                         formatBytes(double(limit.bytes)) + " is available" +
                         (limit.source.empty() ? "" : " under " + limit.source));
    }
}

}  // namespace sculpt
