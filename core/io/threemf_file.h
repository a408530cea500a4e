// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file threemf_file.h
/// @brief 3MF export: the format PrusaSlicer, Bambu Studio and Cura open by default. Unlike STL it
///        says its unit and holds several named objects, each with a colour.

#include "core/io/mesh_frame.h"
#include "core/mesh/triangle_mesh.h"

#include <openvdb/Types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

struct ThreeMfObject {
    std::string name;
    const TriangleMesh* mesh;
    openvdb::Vec3f colour;  ///< sRGB, 0 to 1
};

/// The 3MF unit ("millimeter", "micron", ...) of a document's length unit ("mm", "um", "cm", "m",
/// "in", "ft" and their long names). @throws InputError naming `file` for a unit 3MF has not.
std::string threeMfUnit(const std::string& units, const std::filesystem::path& file);

/// Writes `objects` (LPS, as documents; `frame` as the other mesh writers) into one 3MF file at
/// `path`, atomically: an object per entry with its name and colour (a base material each) and a
/// build item per object, in `units`.
/// @throws InputError naming the file for an unknown unit, a non-finite vertex or a failed write.
void writeThreeMf(const std::vector<ThreeMfObject>& objects, const std::filesystem::path& path,
                  const std::string& units, MeshFrame frame = MeshFrame::Lps);

}  // namespace sculpt
