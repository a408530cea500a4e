// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_output.h
/// @brief The optional `--mesh out.ply` of commands that write a document, and the meshes they
///        write, reported.

#include "core/field/field_image.h"
#include "core/field/piece.h"
#include "core/io/mesh_frame.h"
#include "sculpt/cli/command_report.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sculpt::cli {

/// Adds `--mesh FILE` to a command that writes a document.
void addMeshOutput(CLI::App& cmd, std::string& path);
/// Before any work: refuses an unknown mesh extension or an unwritable target (no-op if empty).
void checkMeshOutput(const std::string& path);
/// Writes the field's welded surface and reports it (no-op if empty).
void writeMeshOutput(const FieldImage& field, const std::string& path, CommandReport& report);

/// Writes each piece's welded surface where it is placed (writePieceMeshes), in `frame`, and
/// reports it (no-op if `path` is empty).
void writePiecesMeshes(const std::vector<Piece>& pieces, const std::string& path, CommandReport& report,
                       MeshFrame frame = MeshFrame::Lps);

}  // namespace sculpt::cli
