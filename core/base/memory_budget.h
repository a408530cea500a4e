// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file memory_budget.h
/// @brief Refuse work that would need more memory than the process may have, before allocating.

#include <cstdint>
#include <string>

namespace sculpt {

/// The memory this process may still take, and what sets that bound.
struct MemoryLimit {
    std::uint64_t bytes = 0;
    std::string source;  ///< empty for the machine's free memory, else e.g. "the control group's memory limit"
};

/// The least of the machine's free memory (MemAvailable from /proc/meminfo, or the physical
/// memory when that is unknown), what the control groups still allow (cgroup_memory.h) and the
/// address space left under RLIMIT_AS (`ulimit -v`).
MemoryLimit memoryLimit();
/// memoryLimit().bytes.
std::uint64_t availableMemoryBytes();

/// The process's address space now (what RLIMIT_AS counts, and what a child inherits).
std::uint64_t addressSpaceBytes();

/// @throws InputError naming `what` and the bound if `bytes` exceeds memoryLimit().
void requireMemory(double bytes, const std::string& what);

}  // namespace sculpt
