// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/document_input.h"

#include "core/base/errors.h"

#include <CLI/CLI.hpp>

#include <filesystem>
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

void addMaskInput(CLI::App& cmd, DocumentInput& input)
{
    cmd.add_option("--mask", input.mask,
                   "FILE[:GRID]: the mask the edit keeps to (1 holds the surface, 0 frees it), taken from\n"
                   "another document: GRID is 'mask' (its first piece's, the default) or 'PIECE.mask'.\n"
                   "'none' edits the whole surface. Default: the document's own mask, if it has one.");
}

namespace {

/// The mask `spec` names ("FILE", "FILE:mask", "FILE:PIECE.mask").
openvdb::FloatGrid::Ptr readMask(const std::string& spec)
{
    std::string path = spec, grid;
    const std::size_t colon = spec.rfind(':');
    std::error_code ec;
    if (colon != std::string::npos && !std::filesystem::exists(spec, ec)) {
        path = spec.substr(0, colon);
        grid = spec.substr(colon + 1);
    }
    VdbPieces document = readVdbPieces(path);
    std::string masks;
    for (const Piece& piece : document.pieces) {
        const std::string name = piece.name + ".mask";
        const bool named = grid == name || ((grid.empty() || grid == "mask") && &piece == &document.pieces.front());
        if (named && piece.field.mask()) return piece.field.maskPtr();
        if (piece.field.mask()) masks += (masks.empty() ? "" : ", ") + name;
    }
    throw InputError(path + ": holds no mask" + (grid.empty() ? "" : " named '" + grid + "'") +
                     (masks.empty() ? " (nothing of it is masked)" : "; its masks: " + masks));
}

void printWarnings(const std::vector<std::string>& warnings)
{
    for (const std::string& warning : warnings) std::cerr << "sculpt: warning: " << warning << "\n";
}

}  // namespace

VdbPieces readPieces(const DocumentInput& input)
{
    if (!input.grid.empty()) {
        VdbDocument document = readDocument(input);
        const std::string name = document.field.grid().getName();
        return {{Piece{{name}, std::move(document.field)}}, std::move(document.companions), {}};
    }
    VdbPieces document = readVdbPieces(input.path);
    printWarnings(document.warnings);
    return document;
}

namespace {

/// `--mask` in place of the field's own mask.
void applyMaskInput(FieldImage& field, const DocumentInput& input)
{
    if (input.mask == "none") {
        field.setMask(nullptr);
    } else if (!input.mask.empty()) {
        const openvdb::FloatGrid::Ptr mask = readMask(input.mask);
        if (mask->transform() != field.grid().transform())
            throw InputError(input.mask + ": the mask is on other voxels than " + input.path +
                             "'s surface (another voxel size or origin)");
        field.setMask(mask);
    }
}

}  // namespace

VdbDocument readDocument(const DocumentInput& input)
{
    VdbDocument document = readVdbDocument(input.path, input.grid);
    printWarnings(document.warnings);
    applyMaskInput(document.field, input);
    return document;
}

VdbPieces readDocumentPieces(const DocumentInput& input)
{
    VdbPieces document = readVdbPieces(input.path, input.grid);
    printWarnings(document.warnings);
    applyMaskInput(document.pieces.front().field, input);
    return document;
}

}  // namespace sculpt::cli
