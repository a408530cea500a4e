#include "sculpt/session/scene_bake.h"

#include "core/field/csg_combine.h"
#include "core/local/speck_removal.h"
#include "core/primitives/primitive_rasterizer.h"
#include "sculpt/session/model_filter.h"

namespace sculpt {

FieldImage bakeScene(FieldImage base, const Scene& scene, const std::string& source, const std::string& baseName,
                     const Progress& progress)
{
    const FieldImage shape =
        rasterizePrimitives(scene.primitives, base.grid().transform(), FieldImage::kDefaultHalfWidthVoxels, progress);
    combine(base, shape, scene.operation);
    removeSpecks(base);
    refuseEmptyResult(base, source, "combining the scene into " + baseName);
    return base;
}

FieldImage bakeScene(const Scene& scene, double voxelSize, const std::string& source)
{
    FieldImage field =
        rasterizePrimitives(scene.primitives, *openvdb::math::Transform::createLinearTransform(voxelSize));
    removeSpecks(field);
    refuseEmptyResult(field, source, "the scene");
    return field;
}

}  // namespace sculpt
