// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file document_text.h
/// @brief The words a document holds, wherever they come from (a `.vdb`'s grid names and
///        metadata, a stroke script's looks, the label names beside a scan, `--units`): a piece's
///        name and the length unit. They are printed in listings and in one-line messages, so they
///        are short and hold no control characters (a newline would split a refusal in two).

#include <string>

namespace sculpt {

/// Bytes a piece's name may take (UTF-8).
inline constexpr std::size_t kMaxPieceNameBytes = 256;
/// Bytes the length unit may take ("mm", "cm", "in", "voxel").
inline constexpr std::size_t kMaxUnitsBytes = 32;

/// Why `name` cannot name a piece ("it is empty"), or "" when it can.
std::string pieceNameProblem(const std::string& name);
/// Why `units` cannot be a length unit, or "" when it can (empty is allowed: no unit).
std::string unitsProblem(const std::string& units);
/// `text` with each control character made a space and cut to at most `maxBytes` (at a whole
/// UTF-8 character): for names other programs wrote beside a scan, taken as best they can be.
std::string printableText(std::string text, std::size_t maxBytes);

}  // namespace sculpt
