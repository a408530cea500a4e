// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file tracked_export.h
/// @brief A tracked mesh's sequence written as files people can play: per segment of constant
///        connectivity, its rest mesh (PLY), a point cache (.pc2, Blender's Mesh Cache modifier)
///        a binary glTF with a morph target per frame (Blender's shape keys, any glTF viewer),
///        a USD text layer with points and velocities per frame (Blender's Mesh Sequence
///        Cache), and segments.json listing which frames each segment covers.

#include "core/tracking/tracked_sequence.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// "segment_0003": segment `index`'s name in the files.
std::string segmentName(std::size_t index);

/// "segment_0003" and its extension: where segment `index`'s files go in `directory`.
std::filesystem::path segmentPath(const std::filesystem::path& directory, std::size_t index,
                                  const std::string& extension);

/// Writes every segment of `sequence` into `directory` (made if missing), frames `fps` apart in
/// the glTF animation: all of it, or (a write failing) none of it. Returns the files written.
/// @throws InputError naming the file if a write fails.
std::vector<std::filesystem::path> writeTrackedSequence(const TrackedSequence& sequence,
                                                        const std::filesystem::path& directory, double fps = 24.0);

}  // namespace sculpt
