// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file point_cache_file.h
/// @brief Point caches (`.pc2`, the format of Blender's Mesh Cache modifier and 3ds Max): the
///        positions of a fixed set of points at every frame.
///
/// Layout, little-endian: "POINTCACHE2\0", int32 version 1, int32 points, float start frame,
/// float sample rate (frames per sample), int32 samples; then samples x points x 3 float32.
/// A mesh whose vertex count and order stay fixed (a tracked mesh's segment) plays it back.

#include <array>
#include <filesystem>
#include <vector>

namespace sculpt {

struct PointCache {
    float startFrame = 0.0f;
    float sampleRate = 1.0f;
    std::vector<std::vector<std::array<float, 3>>> samples;  ///< per sample, the same number of points
};

/// Writes `cache` atomically. @throws InputError naming the file if its directory is missing, the
/// samples differ in size, or the write fails.
void writePointCache(const PointCache& cache, const std::filesystem::path& path);

/// Reads a `.pc2` file. @throws InputError naming the file if its header is not a point cache's
/// or its size is not what the header declares.
PointCache readPointCache(const std::filesystem::path& path);

}  // namespace sculpt
