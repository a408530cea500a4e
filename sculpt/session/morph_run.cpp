// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/morph_run.h"

#include "core/base/memory_budget.h"
#include "core/io/vdb_file.h"
#include "sculpt/session/frame_files.h"
#include "sculpt/session/shape_import.h"

#include <algorithm>

namespace sculpt {

MorphRun morphInto(const FieldImage& source, const std::filesystem::path& targetPath, const MorphOptions& options,
                   const Progress& progress, bool tracked)
{
    MorphRun run;
    run.target = std::make_shared<const FieldImage>(loadShape(targetPath, source.voxelSize(), run.warnings));
    const FieldImage& target = *run.target;
    // Every frame is kept: about the larger shape's grid each (plus the morph's own copies).
    const double frameBytes = double(std::max(source.grid().memUsage(), target.grid().memUsage()));
    requireMemory(1.5 * frameBytes * (options.frames + 4),
                  "keeping " + std::to_string(options.frames) +
                      " morph frames in memory (fewer frames, or `sculpt morph`)");
    if (tracked) run.tracking.emplace();
    const auto onStep = [&](const FieldImage& field) { run.tracking->step(field); };
    run.summary = morph(
        source, target, options,
        [&](const MorphFrame& frame) {
            run.frames.push_back(frame.field.deepCopy());
            if (tracked) run.tracking->frame(frame.field);
        },
        progress, tracked ? std::function<void(const FieldImage&)>(onStep) : nullptr);
    return run;
}

void writeFrames(const std::vector<FieldImage>& frames, const std::filesystem::path& dir, WrittenOutputs& outputs)
{
    outputs.directory(dir);
    for (std::size_t i = 0; i < frames.size(); ++i) {
        writeFieldImage(frames[i], outputs.file(framePath(dir, int(i), "vdb")));
        if (i == 0) outputs.requireRoomFor(frames.size() - 1, 1.0, "the other frames");
    }
}

}  // namespace sculpt
