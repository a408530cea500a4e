// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file process_memory.h
/// @brief What this process holds in memory, as the kernel counts it (Linux /proc/self/status).

#include <cstddef>

namespace sculpt::ui {

/// Bytes resident now (VmRSS), or 0 where the kernel does not say.
std::size_t residentBytes();
/// The most bytes ever resident (VmHWM), or 0 where the kernel does not say.
std::size_t peakResidentBytes();

}  // namespace sculpt::ui
