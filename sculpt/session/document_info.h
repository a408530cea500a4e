// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file document_info.h
/// @brief A document's measures as JSON, the keys `sculpt info --json` prints and the Python
///        module's info() returns (data/reports.schema.json): per piece and in total, the grids
///        of its file, the scan it keeps.

#include "core/io/vdb_file.h"
#include "core/io/vdb_layout.h"
#include "core/mesh/field_measures.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace sculpt {

/// One field's measures: voxel_size, units, half_width_voxels, active_voxels, memory_bytes,
/// bbox_min, bbox_max, volume, area, euler_characteristic, components.
nlohmann::json measuresJson(const FieldMeasures& m, const std::string& units);
/// The pieces together: sums, the union of their boxes, the first's voxel size and band.
FieldMeasures totalMeasures(const std::vector<FieldMeasures>& pieces);
/// The scan the document keeps (kept_scan.h): its samples, where they came from, and what they
/// cost in memory and in the file at `path` (laid out as `layout`); null when it keeps none.
/// @throws InputError naming `path` if its record is damaged.
nlohmann::json keptScanJson(const VdbCompanions& companions, const VdbLayout& layout, const std::string& path);
/// The first piece's thinnest wall under `under` as JSON: null when none is thinner.
nlohmann::json thinnestJson(const FieldImage& field, double under);

/// The whole report of the document `read` from the file at `path` (laid out as `layout`); with
/// `thickness` > 0, its thinnest wall under that too.
nlohmann::json documentInfo(const VdbPieces& read, const VdbLayout& layout, const std::string& path, double thickness);

}  // namespace sculpt
