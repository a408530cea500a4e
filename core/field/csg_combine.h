// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file csg_combine.h
/// @brief Combines a shape into the sculpt: union, difference, intersection or replace.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"

#include <string>

namespace sculpt {

enum class CsgOperation { Union, Difference, Intersection, Replace };

/// "union", "difference", "intersection", "replace". @throws InputError for other names.
CsgOperation csgFromName(const std::string& name);
const char* csgName(CsgOperation operation);

/// sculpt = sculpt op shape, both on the same voxels. Union (min) and difference
/// (max(phi, -phi_shape)) visit only the leaves the shape covers; intersection and replace change
/// the whole sculpt by nature. Marks and returns the touched leaves.
/// @throws InputError if the two grids' transforms differ.
DirtyRegion combine(FieldImage& sculpt, const FieldImage& shape, CsgOperation operation);

/// OpenVDB's CSG of two whole level sets on the same voxels, a = a op b (union, difference or
/// intersection; b is consumed): for edits of whole regions (cuts, shells, islands), which keeps
/// inside tiles whole instead of making leaves of them. In this one unit: its templates are heavy.
void combineWhole(openvdb::FloatGrid& a, openvdb::FloatGrid& b, CsgOperation operation);

}  // namespace sculpt
