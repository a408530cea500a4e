// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file text_format.h
/// @brief Numbers as people read them, for messages and reports.

#include <cstdint>
#include <string>

namespace sculpt {

/// Shortest readable form of a value: "50", "0.5", "1e+12" (printf %g).
std::string formatNumber(double value);

/// A count with thousands separated: "8,204,311".
std::string formatCount(std::uint64_t count);

/// Seconds to the millisecond: "0.27", "8.533".
std::string formatSeconds(double seconds);

/// "1.5 GiB", "320 KiB": bytes in binary units.
std::string formatBytes(double bytes);

}  // namespace sculpt
