#include "sculpt/cli/edit_document.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/io/vdb_file.h"
#include "core/motion/volume_estimate.h"
#include "sculpt/cli/progress_bar.h"

namespace sculpt::cli {

void refuseEmptyResult(const FieldImage& field, const std::string& source, const std::string& operation)
{
    // Less than a voxel of volume left is nothing a user can see or print either.
    const double voxel = field.voxelSize() * field.voxelSize() * field.voxelSize();
    if (!field.enclosesSomething() || estimateVolumeArea(field.grid()).volume < voxel) {
        throw InputError(source + ": " + operation +
                         " leaves nothing of the model (no surface remains); nothing written");
    }
}

FieldImage editDocument(const std::string& input, const std::string& output, const std::string& label,
                        const std::function<void(FieldImage&, const Progress&)>& edit)
{
    AtomicFile::checkTarget(output);
    FieldImage field = readFieldImage(input);
    {
        ProgressBar bar(label);
        edit(field, bar.callback());
    }
    refuseEmptyResult(field, input, label);
    writeFieldImage(field, output);
    return field;
}

}  // namespace sculpt::cli
