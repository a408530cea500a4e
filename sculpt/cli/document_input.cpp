#include "sculpt/cli/document_input.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace sculpt::cli {

void addDocumentInput(CLI::App& cmd, DocumentInput& input, const std::string& what)
{
    cmd.add_option("input", input.path, what)->required();
    cmd.add_option("--grid,--piece", input.grid,
                   "the piece (a level-set grid) to use when the file holds several (default: the first\n"
                   "piece, the one named 'surface', else the only level set; `sculpt info` lists them).\n"
                   "The others are kept.");
}

namespace {

void printWarnings(const std::vector<std::string>& warnings)
{
    for (const std::string& warning : warnings) std::cerr << "sculpt: warning: " << warning << "\n";
}

}  // namespace

std::vector<Piece> readPieces(const DocumentInput& input)
{
    if (!input.grid.empty()) {
        VdbDocument document = readDocument(input);
        const std::string name = document.field.grid().getName();
        return {Piece{{name}, std::move(document.field)}};
    }
    VdbPieces document = readVdbPieces(input.path);
    printWarnings(document.warnings);
    return std::move(document.pieces);
}

VdbDocument readDocument(const DocumentInput& input)
{
    VdbDocument document = readVdbDocument(input.path, input.grid);
    printWarnings(document.warnings);
    return document;
}

}  // namespace sculpt::cli
