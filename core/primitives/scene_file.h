// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scene_file.h
/// @brief Primitive scenes in JSON (schema: data/scene.schema.json; format: README).
///
///     {"iso": 0.5, "operation": "union", "voxel_size": 0.5,
///      "primitives": [{"name": "head", "kernel": "soft-object", "radius": 8, "strength": 1,
///                      "skeleton": {"type": "point", "position": [0, 0, 10]},
///                      "neighbours": ["body"]}, ...]}
/// Skeletons: point {position}, segment {from, to}, triangle {points: [a, b, c]},
/// box {center, half_extents, rotation_degrees: [x, y, z] (optional, applied x then y then z)}.
/// If any primitive lists neighbours, blending follows that graph; otherwise all primitives sum.

#include "core/field/csg_combine.h"
#include "core/primitives/primitive_set.h"

#include <filesystem>
#include <optional>
#include <string>

namespace sculpt {

struct Scene {
    PrimitiveSet primitives;
    CsgOperation operation = CsgOperation::Union;
    std::optional<double> voxelSize;  ///< suggested voxel size, if the file gives one
};

/// Parses a scene from JSON text; `source` names it in messages.
/// @throws InputError naming the source, the primitive (index and name) and the field at fault.
Scene parseScene(const std::string& text, const std::string& source);

/// Reads and parses a scene file. @throws InputError as parseScene, or if unreadable.
Scene readScene(const std::filesystem::path& path);

/// The scene as JSON text that parseScene reads back to the same primitives, numbers exactly
/// (box rotations to within rounding). Unnamed primitives a neighbours graph refers to are
/// named "p<index>".
std::string writeScene(const Scene& scene);

}  // namespace sculpt
