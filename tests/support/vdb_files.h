// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file vdb_files.h
/// @brief `.vdb` files as other programs write them: several named grids, metadata of their own.

#include "core/field/field_image.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sculpt::test {

/// Writes the fields' grids (copies, renamed) in this order with OpenVDB's own writer.
void writeNamedGrids(const std::filesystem::path& path, const std::vector<std::pair<std::string, FieldImage>>& grids,
                     const openvdb::MetaMap& meta = {});

}  // namespace sculpt::test
