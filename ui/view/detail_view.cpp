#include "ui/view/detail_view.h"

namespace sculpt::ui {

bool drawsCoarse(const glm::dvec3& lo, const glm::dvec3& hi, double voxelSize, const DetailView& view)
{
    if (view.still || !view.pixelSizeAt) return false;
    if (view.brushRadius >= 0.0) {
        const glm::dvec3 nearest = glm::clamp(view.brushCentre, lo, hi);
        if (glm::length(nearest - view.brushCentre) <= view.brushRadius) return false;
    }
    // The chunk's point nearest the eye is where its voxels look largest.
    const glm::dvec3 nearest = glm::clamp(view.eye, lo, hi);
    if (nearest == view.eye) return false;  // the eye is inside the chunk
    return voxelSize < kCoarseBelowVoxelPixels * view.pixelSizeAt(nearest);
}

}  // namespace sculpt::ui
