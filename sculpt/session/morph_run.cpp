#include "sculpt/session/morph_run.h"

#include "core/io/vdb_file.h"
#include "sculpt/session/frame_files.h"
#include "sculpt/session/shape_import.h"

namespace sculpt {

MorphRun morphInto(const FieldImage& source, const std::filesystem::path& targetPath, const MorphOptions& options,
                   const Progress& progress)
{
    MorphRun run;
    const FieldImage target = loadShape(targetPath, source.voxelSize(), run.warnings);
    run.summary = morph(
        source, target, options,
        [&](const MorphFrame& frame) { run.frames.emplace_back(frame.field.grid().deepCopy(), source.units()); },
        progress);
    return run;
}

void writeFrames(const std::vector<FieldImage>& frames, const std::filesystem::path& dir)
{
    prepareDirectory(dir);
    for (std::size_t i = 0; i < frames.size(); ++i) writeFieldImage(frames[i], framePath(dir, int(i), "vdb"));
}

}  // namespace sculpt
