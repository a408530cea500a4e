#pragma once
/// @file mesh_output.h
/// @brief The optional `--mesh out.ply` of commands that write a document.

#include "core/field/field_image.h"

#include <string>

namespace sculpt::cli {

/// Before any work: refuses an unknown mesh extension or an unwritable target (no-op if empty).
void checkMeshOutput(const std::string& path);
/// Writes the field's welded surface and reports it on stdout (no-op if empty).
void writeMeshOutput(const FieldImage& field, const std::string& path);

}  // namespace sculpt::cli
