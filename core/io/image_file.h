// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file image_file.h
/// @brief Writing a rendered image: multi-layer OpenEXR for compositing, 8-bit PNG for a picture.
///
/// OpenEXR (through the OpenEXR library, ZIP compressed): half-float R, G, B, A (premultiplied,
/// linear), float Z (camera distance, +infinity where nothing was hit) and float N.X, N.Y, N.Z
/// (world normal); the header carries the camera: `worldToCamera` (OpenEXR's standard attribute)
/// and `cameraPosition`, `cameraLookAt`, `cameraUp` (v3f), `cameraFov` (vertical, degrees).
/// PNG (VTK's writer): the colour tone-mapped for a screen (clamped, sRGB), with alpha when the
/// background is transparent. Both are written to a temporary file and renamed into place.

#include "core/render/camera.h"
#include "core/render/rendered_image.h"

#include <filesystem>
#include <string>

namespace sculpt {

enum class ImageFormat { Exr, Png };

/// By extension: .exr or .png. @throws InputError naming the path for any other.
ImageFormat imageFormatOf(const std::filesystem::path& path);

/// Writes `image` in the format of `path`'s extension. @throws InputError naming the path if it
/// cannot be written (no partial file is left).
void writeImage(const RenderedImage& image, const Camera& camera, const std::filesystem::path& path);

}  // namespace sculpt
