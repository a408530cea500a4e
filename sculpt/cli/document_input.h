#pragma once
/// @file document_input.h
/// @brief A command's input document: its path and, for files of other programs holding
///        several level sets, the grid to use (`--grid NAME`).

#include "core/io/vdb_file.h"

#include <string>

namespace CLI {
class App;
}

namespace sculpt::cli {

struct DocumentInput {
    std::string path;
    std::string grid;  ///< empty: "surface", else the only level set
};

/// Adds the positional `input` (described by `what`) and `--grid` to `cmd`.
void addDocumentInput(CLI::App& cmd, DocumentInput& input, const std::string& what);

/// Reads the document, printing its warnings (a grid left out, a band rebuilt) on stderr.
VdbDocument readDocument(const DocumentInput& input);

}  // namespace sculpt::cli
