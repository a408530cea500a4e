// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file ray_tracer.h
/// @brief Final images of a sculpt, ray-traced against the level set itself.
///
/// Every primary ray is intersected with the zero level set by OpenVDB's LevelSetRayIntersector
/// (it walks the tree's own hierarchy, then bisects the crossing: the exact surface, not a mesh
/// of it), one intersector per thread. Shading reads as clay: a diffuse base lit by a key and a
/// fill light that move with the camera (so a turntable looks like the model turning in a fixed
/// studio), a soft specular highlight from the key, and ambient light darkened by ambient
/// occlusion: a few cosine-distributed short rays from the hit point, against the level set too
/// (a pixel's budget of them shared among its samples, so anti-aliasing does not multiply it).
/// Each pixel takes several stratified samples (jittered on a grid) for anti-aliasing. Every
/// random number is a hash of the pixel, the sample and the seed, so the image is the same bit
/// for bit whatever the thread count. Pixels are shaded in parallel, a row of 16 x 16 tiles at
/// a time (progress is reported per row).

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/render/camera.h"
#include "core/render/rendered_image.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sculpt {

struct RenderOptions {
    int width = 1024;              ///< pixels
    int height = 768;              ///< pixels
    int samples = 4;               ///< per pixel, rounded up to a square number for the strata
    int occlusionRays = 8;         ///< ambient-occlusion rays per hit (0: no occlusion)
    double occlusionReach = 0.15;  ///< length of those rays, as a fraction of the model's size
    /// Opaque background colour (linear RGB), or none for a transparent background.
    std::optional<openvdb::Vec3d> background = openvdb::Vec3d(0.16, 0.16, 0.18);
    std::uint64_t seed = 1;

    static constexpr int kMaxSide = 16384;
    /// @throws InputError naming the field: a side outside [1, kMaxSide], samples outside
    ///         [1, 1024], negative occlusion rays or reach, a non-finite background.
    void validate() const;
};

struct RenderReport {
    std::size_t coveredPixels = 0;      ///< pixels where some sample hit the surface
    std::vector<std::string> warnings;  ///< camera inside the surface, nothing in view
};

/// Renders `field` seen from `camera`.
/// @throws InputError for bad options or camera, or an image that would not fit in memory;
///         Cancelled if `progress` says stop.
/// Cost: samples x pixels x (one ray, plus occlusionRays where it hits).
RenderedImage renderField(const FieldImage& field, const Camera& camera, const RenderOptions& options,
                          RenderReport& summary, const Progress& progress = {});

}  // namespace sculpt
