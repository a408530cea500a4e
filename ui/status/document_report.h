// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file document_report.h
/// @brief What the window's report says of the document: its grids' checksums, its pieces and
///        their placements, its file, title, modified mark and undo depth.

#include <nlohmann/json_fwd.hpp>

namespace sculpt {
class Document;
}  // namespace sculpt

namespace sculpt::ui {

void reportDocument(nlohmann::json& out, const Document& document);

}  // namespace sculpt::ui
