// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file morph_run.h
/// @brief A morph of the model into a target file with every frame kept in memory (the
///        window's Morph panel plays, scrubs and exports them): the same frames `sculpt morph`
///        writes for the same inputs.

#include "core/base/progress.h"
#include "core/base/written_outputs.h"
#include "core/motion/morph.h"
#include "sculpt/session/morph_tracking.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sculpt {

struct MorphRun {
    std::vector<FieldImage> frames;  ///< frame 0 is the (aligned) source, the last the result
    MorphSummary summary;
    std::vector<std::string> warnings;         ///< from reading the target
    std::shared_ptr<const FieldImage> target;  ///< as read, at the source's voxel size
    std::optional<MorphTracking> tracking;     ///< the tracked mesh, when asked for
};

/// Morphs `source` into the shape in `targetPath` (a .vdb document, a scan or a mesh, read at the
/// source's voxel size as `sculpt morph` does), tracking a mesh along if `tracked` (every step
/// then runs on: a watched morph resumes from no kept state). Memory: every frame.
/// @throws InputError naming the file or option at fault, or if the frames would not fit in the
///         memory available; Cancelled if progress says stop.
MorphRun morphInto(const FieldImage& source, const std::filesystem::path& targetPath, const MorphOptions& options,
                   const Progress& progress = {}, bool tracked = false);

/// Writes `frames` as DIR/frame_0000.vdb ... (DIR made if missing), noted in `outputs` (taken
/// back unless the caller keeps them).
/// @throws InputError naming the directory or file that cannot be written.
void writeFrames(const std::vector<FieldImage>& frames, const std::filesystem::path& dir, WrittenOutputs& outputs);

}  // namespace sculpt
