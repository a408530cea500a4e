#pragma once
/// @file text_format.h
/// @brief Numbers as people read them, for messages and reports.

#include <string>

namespace sculpt {

/// Shortest readable form of a value: "50", "0.5", "1e+12" (printf %g).
std::string formatNumber(double value);

/// "1.5 GiB", "320 KiB": bytes in binary units.
std::string formatBytes(double bytes);

}  // namespace sculpt
