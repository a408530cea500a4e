// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file edit_document.h
/// @brief The shape of every editing command: read a document, change it with a progress bar,
///        write the result atomically (the input is never touched).

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "sculpt/cli/document_input.h"

#include <functional>
#include <string>

namespace sculpt::cli {

/// Reads `input` (its chosen grid), applies `edit` (drawing a bar labelled `label`), writes `output`; returns the
/// edited field for the command's report. The file's other grids and metadata are written too. Fails before any work if `output` cannot be written,
/// and refuses (writing nothing) an edit that leaves nothing of the model.
FieldImage editDocument(const DocumentInput& input, const std::string& output, const std::string& label,
                        const std::function<void(FieldImage&, const Progress&)>& edit);

}  // namespace sculpt::cli
