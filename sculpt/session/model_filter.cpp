#include "sculpt/session/model_filter.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/motion/surface_flows.h"
#include "core/motion/volume_estimate.h"

#include <cmath>

namespace sculpt {

std::string filterLabel(const ModelFilter& filter)
{
    if (filter.kind == ModelFilter::Kind::Offset) {
        return "offset " + std::string(filter.distanceWorld > 0.0 ? "+" : "") + formatNumber(filter.distanceWorld);
    }
    return "smooth " + std::to_string(filter.iterations) + (filter.keepVolume ? " (keep volume)" : "");
}

FieldImage applyFilter(FieldImage field, const ModelFilter& filter, const std::string& source, const Progress& progress)
{
    if (filter.kind == ModelFilter::Kind::Offset && !std::isfinite(filter.distanceWorld)) {
        throw InputError("offset distance must be finite");
    }
    if (filter.kind == ModelFilter::Kind::Smooth) {
        smooth(field, filter.iterations, filter.keepVolume, progress);
    } else {
        offset(field, filter.distanceWorld, progress);
    }
    refuseEmptyResult(field, source, filterLabel(filter));
    return field;
}

void refuseEmptyResult(const FieldImage& field, const std::string& source, const std::string& operation)
{
    // Less than a voxel of volume left is nothing a user can see or print either.
    const double voxel = field.voxelSize() * field.voxelSize() * field.voxelSize();
    if (!field.enclosesSomething() || estimateVolumeArea(field.grid()).volume < voxel) {
        throw InputError(source + ": " + operation +
                         " leaves nothing of the model (no surface remains); nothing written");
    }
}

}  // namespace sculpt
