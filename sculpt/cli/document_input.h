// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file document_input.h
/// @brief A command's input document: its path and, for files of other programs holding
///        several level sets, the grid to use (`--grid NAME`).

#include "core/io/vdb_file.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sculpt::cli {

struct DocumentInput {
    std::string path;
    std::string grid;  ///< a piece's or grid's name; empty: the edited one, "surface" or the only level set
    std::string mask;  ///< `--mask FILE[:GRID]` or "none"; empty: the document's own mask
};

/// Adds `--mask` to an editing command: the mask its edit keeps to, instead of the document's own.
void addMaskInput(CLI::App& cmd, DocumentInput& input);

/// Adds the positional `input` (described by `what`) and `--grid` to `cmd`.
void addDocumentInput(CLI::App& cmd, DocumentInput& input, const std::string& what);

/// Every piece of the document, or the one `grid` names, and its other grids, printing its
/// warnings on stderr.
VdbPieces readPieces(const DocumentInput& input);

/// Reads the document, printing its warnings (a grid left out, a band rebuilt) on stderr, with the
/// mask `--mask` names in place of its own.
/// @throws InputError naming the mask's file if it holds no such mask or one on other voxels.
VdbDocument readDocument(const DocumentInput& input);
/// Every piece of the document, the first the one `--grid` names (or the edited one) with the
/// mask `--mask` names, printing the warnings as readDocument.
VdbPieces readDocumentPieces(const DocumentInput& input);

}  // namespace sculpt::cli
