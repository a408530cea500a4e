// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/scene_bake.h"

#include "core/base/errors.h"
#include "core/field/csg_combine.h"
#include "core/field/voxel_size.h"
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
    const openvdb::math::Transform::Ptr xform = [&] {
        try {
            return voxelTransform(voxelSize);
        } catch (const InputError& e) {
            throw InputError(source + ": " + e.what(), e.remedy());
        }
    }();
    FieldImage field = rasterizePrimitives(scene.primitives, *xform);
    removeSpecks(field);
    refuseEmptyResult(field, source, "the scene");
    return field;
}

}  // namespace sculpt
