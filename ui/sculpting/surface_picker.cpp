// SPDX-License-Identifier: Apache-2.0
#include "ui/sculpting/surface_picker.h"

#include "core/field/surface_ray.h"

namespace sculpt::ui {

void SurfacePicker::reset()
{
    mBox = openvdb::CoordBBox();
    mFieldId = 0;
    mFrozen = false;
}

void SurfacePicker::refreshBox(const FieldImage& field, std::uint64_t fieldVersion)
{
    if (mFieldId == field.id() && mVersion == fieldVersion) return;
    mBox = openvdb::CoordBBox();  // a pass over the tree's nodes: once per change, never per pick
    field.grid().tree().evalLeafBoundingBox(mBox);
    mFieldId = field.id();
    mVersion = fieldVersion;
}

void SurfacePicker::freeze(const FieldImage& field, std::uint64_t fieldVersion)
{
    refreshBox(field, fieldVersion);
    mFrozen = true;
}

std::optional<SurfaceHit> SurfacePicker::pick(const FieldImage& field, std::uint64_t fieldVersion, const Ray& ray,
                                              const LeafJournal* editedSince)
{
    if (!mFrozen) refreshBox(field, fieldVersion);
    const auto crossing =
        firstSurfaceCrossing(PreEditField(field, editedSince), mBox, {ray.origin.x, ray.origin.y, ray.origin.z},
                             {ray.direction.x, ray.direction.y, ray.direction.z});
    if (!crossing) return std::nullopt;
    const openvdb::Vec3d p = crossing->position, n = crossing->normal;
    return SurfaceHit{{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}};
}

}  // namespace sculpt::ui
