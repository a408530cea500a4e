#pragma once
/// @file memory_budget.h
/// @brief Refuse work that would need more memory than the machine has, before allocating.

#include <cstdint>
#include <string>

namespace sculpt {

/// Memory the system could give us now, in bytes (MemAvailable from /proc/meminfo, or the
/// physical memory when that is unknown).
std::uint64_t availableMemoryBytes();

/// @throws InputError naming `what` if `bytes` exceeds what the machine has available.
void requireMemory(double bytes, const std::string& what);

}  // namespace sculpt
