// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file cgal_data.h
/// @brief Meshes nobody here wrote: CGAL's sample data (Debian's libcgal-demo ships them in
///        /usr/share/doc/libcgal-dev/data.tar.gz), extracted once per process on demand.

#include <filesystem>
#include <string>

namespace sculpt::test {

/// The path of CGAL's data/`member` (e.g. "images/liver.inr.gz"), extracted into a directory
/// removed at exit; empty if the archive is missing (install libcgal-demo).
std::filesystem::path cgalData(const std::string& member);

/// cgalData of data/meshes/`name` (e.g. "camel.off").
inline std::filesystem::path cgalMesh(const std::string& name) { return cgalData("meshes/" + name); }

}  // namespace sculpt::test
