// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/model_filter.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/motion/surface_flows.h"
#include "core/motion/volume_estimate.h"
#include "core/solids/islands.h"

#include <cmath>

namespace sculpt {

std::string filterLabel(const ModelFilter& filter)
{
    switch (filter.kind) {
    case ModelFilter::Kind::Offset:
        return "offset " + std::string(filter.distanceWorld > 0.0 ? "+" : "") + formatNumber(filter.distanceWorld);
    case ModelFilter::Kind::Hollow:
        return "hollow " + formatNumber(filter.hollow.thicknessWorld) + (filter.drain ? " (drained)" : "");
    case ModelFilter::Kind::RemoveIslands: return "remove islands under " + formatNumber(filter.minIslandVolume);
    case ModelFilter::Kind::Smooth: break;
    }
    return "smooth " + std::to_string(filter.iterations) + (filter.keepVolume ? " (keep volume)" : "");
}

namespace {

InputError nothingLeft(const std::string& source, const std::string& operation)
{
    return InputError(source + ": " + operation + " leaves nothing of the model (no surface remains); nothing written");
}

/// Limits that keep a filter's work bounded: its cost grows with the iterations, or with the
/// distance in voxels.
void refuseUnboundedWork(const FieldImage& field, const ModelFilter& filter, const std::string& source)
{
    if (filter.kind == ModelFilter::Kind::Smooth &&
        (filter.iterations < 1 || filter.iterations > kMaxSmoothIterations)) {
        throw InputError(source + ": smoothing takes 1 to " + std::to_string(kMaxSmoothIterations) +
                         " iterations (got " + std::to_string(filter.iterations) + ")");
    }
    if (filter.kind != ModelFilter::Kind::Offset) return;
    openvdb::CoordBBox box;
    field.grid().tree().evalLeafBoundingBox(box);
    const double size = box.dim().asVec3d().length() * field.voxelSize();
    if (filter.distanceWorld < -size) throw nothingLeft(source, filterLabel(filter));
    if (filter.distanceWorld > size) {
        throw InputError(source + ": an offset of " + formatNumber(filter.distanceWorld) +
                         " is larger than the model (" + formatNumber(size) +
                         " across); offset at most that at a time");
    }
}

/// The shell hollow() makes, drained as asked, keeping the field's mask.
FieldImage hollowed(const FieldImage& field, const ModelFilter& filter, const Progress& progress)
{
    HollowResult shell = hollow(field, filter.hollow, filter.up, progress);
    if (filter.drain) {
        cutDrainHoles(shell.field, drainHolesUnder(shell.cavityBottoms, filter.up, filter.hollow.thicknessWorld,
                                                   filter.drainRadiusWorld));
    }
    shell.field.setMask(field.maskPtr());
    return std::move(shell.field);
}

}  // namespace

FieldImage applyFilter(FieldImage field, const ModelFilter& filter, const std::string& source, const Progress& progress)
{
    if (filter.kind == ModelFilter::Kind::Offset && !std::isfinite(filter.distanceWorld)) {
        throw InputError("offset distance must be finite");
    }
    refuseUnboundedWork(field, filter, source);
    switch (filter.kind) {
    case ModelFilter::Kind::Smooth: smooth(field, filter.iterations, filter.keepVolume, progress); break;
    case ModelFilter::Kind::Offset: offset(field, filter.distanceWorld, progress); break;
    case ModelFilter::Kind::Hollow: field = hollowed(field, filter, progress); break;
    case ModelFilter::Kind::RemoveIslands: removeIslandsUnder(field, filter.minIslandVolume); break;
    }
    refuseEmptyResult(field, source, filterLabel(filter));
    return field;
}

void refuseEmptyResult(const FieldImage& field, const std::string& source, const std::string& operation)
{
    // Less than a voxel of volume left is nothing a user can see or print either.
    const double voxel = field.voxelSize() * field.voxelSize() * field.voxelSize();
    if (!field.enclosesSomething() || estimateVolumeArea(field.grid()).volume < voxel) {
        throw nothingLeft(source, operation);
    }
}

}  // namespace sculpt
