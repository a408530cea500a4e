#include "ui/sculpting/surface_picker.h"

#include <openvdb/tools/RayIntersector.h>

namespace sculpt::ui {

struct SurfacePicker::Intersector {
    explicit Intersector(const openvdb::FloatGrid& grid) : isect(grid) {}
    openvdb::tools::LevelSetRayIntersector<openvdb::FloatGrid> isect;
};

SurfacePicker::SurfacePicker() = default;
SurfacePicker::~SurfacePicker() = default;

void SurfacePicker::reset()
{
    mIntersector.reset();
    mFrozen.reset();
    mFieldId = 0;
}

void SurfacePicker::freeze(const FieldImage& field)
{
    mFrozen = field.grid().deepCopy();
    mIntersector = std::make_unique<Intersector>(*mFrozen);
}

void SurfacePicker::thaw()
{
    mFrozen.reset();
    mIntersector.reset();
}

std::optional<SurfaceHit> SurfacePicker::pick(const FieldImage& field, std::uint64_t fieldVersion, const Ray& ray)
{
    if (field.grid().tree().activeVoxelCount() == 0) return std::nullopt;
    if (!mFrozen && (!mIntersector || mFieldId != field.id() || mVersion != fieldVersion)) {
        mIntersector = std::make_unique<Intersector>(field.grid());
        mFieldId = field.id();
        mVersion = fieldVersion;
    }
    const openvdb::math::Ray<double> r(openvdb::Vec3d(ray.origin.x, ray.origin.y, ray.origin.z),
                                       openvdb::Vec3d(ray.direction.x, ray.direction.y, ray.direction.z));
    openvdb::Vec3d hit, normal;
    if (!mIntersector->isect.intersectsWS(r, hit, normal)) return std::nullopt;
    if (normal.length() > 0.0) normal.normalize();
    return SurfaceHit{{hit.x(), hit.y(), hit.z()}, {normal.x(), normal.y(), normal.z()}};
}

}  // namespace sculpt::ui
