// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file rendered_image.h
/// @brief What a render produces: colour with coverage, camera distance and surface normal per
///        pixel, in linear light, rows from the top.

#include <cstddef>
#include <vector>

namespace sculpt {

struct RenderedImage {
    int width = 0, height = 0;
    /// R, G, B, A per pixel, premultiplied by A (the share of the pixel the surface covers; 1
    /// everywhere with an opaque background), linear.
    std::vector<float> rgba;
    /// Distance from the camera to the nearest surface point seen in the pixel, world units;
    /// +infinity where no sample hit the surface.
    std::vector<float> depth;
    /// World-space unit normal (x, y, z) of the surface seen in the pixel; 0 where nothing was hit.
    std::vector<float> normal;

    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
};

}  // namespace sculpt
