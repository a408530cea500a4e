#pragma once
/// @file mesh_output.h
/// @brief The optional `--mesh out.ply` of commands that write a document.

#include "core/field/field_image.h"
#include "core/field/piece.h"
#include "core/io/mesh_frame.h"

#include <string>
#include <vector>

namespace sculpt::cli {

/// Before any work: refuses an unknown mesh extension or an unwritable target (no-op if empty).
void checkMeshOutput(const std::string& path);
/// Writes the field's welded surface and reports it on stdout (no-op if empty).
void writeMeshOutput(const FieldImage& field, const std::string& path);

/// Writes each piece's welded surface where it is placed (writePieceMeshes), in `frame`, and
/// reports it on stdout.
void writePiecesMeshes(const std::vector<Piece>& pieces, const std::string& path, MeshFrame frame = MeshFrame::Lps);

}  // namespace sculpt::cli
