#include "sculpt/cli/document_input.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace sculpt::cli {

void addDocumentInput(CLI::App& cmd, DocumentInput& input, const std::string& what)
{
    cmd.add_option("input", input.path, what)->required();
    cmd.add_option("--grid", input.grid,
                   "the grid to use when the file holds several (default: the one named 'surface',\n"
                   "else the only level set; `sculpt info` lists them). The others are kept.");
}

VdbDocument readDocument(const DocumentInput& input)
{
    VdbDocument document = readVdbDocument(input.path, input.grid);
    for (const std::string& warning : document.warnings) std::cerr << "sculpt: warning: " << warning << "\n";
    return document;
}

}  // namespace sculpt::cli
