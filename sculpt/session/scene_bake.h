// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scene_bake.h
/// @brief A primitive scene baked into a document: what `sculpt build --into` and the window's
///        Primitives panel do, so both give the same grid.

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/primitives/scene_file.h"

#include <string>

namespace sculpt {

/// The scene rasterized on `base`'s voxels and combined into it by the scene's operation, specks
/// removed. @throws InputError naming `source` and `baseName` if nothing of the model is left.
FieldImage bakeScene(FieldImage base, const Scene& scene, const std::string& source, const std::string& baseName,
                     const Progress& progress = {});

/// The scene alone on voxels of `voxelSize`, specks removed.
/// @throws InputError naming `source` if the scene encloses nothing.
FieldImage bakeScene(const Scene& scene, double voxelSize, const std::string& source);

}  // namespace sculpt
