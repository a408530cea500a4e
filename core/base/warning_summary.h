// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file warning_summary.h
/// @brief Warnings said once per kind: a label map of 2,000 labels must not print 2,000 lines
///        that differ only in a piece's name and a count.

#include <string>
#include <vector>

namespace sculpt {

/// `warnings` with each kind (the same text once a leading "piece 'NAME': " is set aside and
/// numbers are blanked) said at most `keep` times, then one line "... and N more like it".
std::vector<std::string> summarisedWarnings(const std::vector<std::string>& warnings, std::size_t keep = 3);

}  // namespace sculpt
