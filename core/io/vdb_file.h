#pragma once
/// @file vdb_file.h
/// @brief Field images in OpenVDB's `.vdb` format, readable by Houdini, Blender and OpenVDB tools.
///
/// A document holds one float level-set grid named "surface" and file metadata:
///   sculpt.format_version (int)   — kVdbFormatVersion; newer files are refused
///   sculpt.units          (string)— length unit of world coordinates, e.g. "mm"
///   sculpt.voxel_size     (double)— redundant with the transform; a mismatch means damage
///   sculpt.checksum       (string)— gridChecksum() in hex; a mismatch means damage
/// Files from other programs (no sculpt metadata) are accepted if they hold a float level set;
/// the first such grid is used.

#include "core/field/field_image.h"

#include <filesystem>

namespace sculpt {

/// Version of our metadata layout, written into every document.
constexpr int kVdbFormatVersion = 1;

/// Reads a field image.
/// @throws InputError naming the file if it is missing, not an OpenVDB file, truncated or
///         corrupt, holds no float level set, was written by a newer format version, or would
///         need more memory than is available.
FieldImage readFieldImage(const std::filesystem::path& path);

/// Writes a field image atomically (temporary file, then rename): a failure or a crash leaves
/// any previous file untouched and no partial file behind.
/// @throws InputError naming the file if its directory does not exist or it cannot be written.
void writeFieldImage(const FieldImage& field, const std::filesystem::path& path);

}  // namespace sculpt
