#pragma once
/// @file mesh_output.h
/// @brief The optional `--mesh out.ply` of commands that write a document.

#include "core/field/field_image.h"
#include "core/field/piece.h"

#include <string>
#include <vector>

namespace sculpt::cli {

/// Before any work: refuses an unknown mesh extension or an unwritable target (no-op if empty).
void checkMeshOutput(const std::string& path);
/// Writes the field's welded surface and reports it on stdout (no-op if empty).
void writeMeshOutput(const FieldImage& field, const std::string& path);

/// Writes each piece's welded surface and reports it on stdout: one piece to `path`; several to
/// one OBJ file of an object each, or (.ply, .stl) to a file each, named `path`'s stem, a dash
/// and the piece's name ("head-label_3.ply"), every target checked before any is written.
void writePiecesMeshes(const std::vector<Piece>& pieces, const std::string& path);

}  // namespace sculpt::cli
