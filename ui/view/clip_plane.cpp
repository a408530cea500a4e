// SPDX-License-Identifier: Apache-2.0
#include "ui/view/clip_plane.h"

#include <vtkPlane.h>
#include <vtkPlaneCollection.h>

namespace sculpt::ui {

namespace {

/// Where the plane lies while off: beyond any model (2^19 voxels of any size we allow).
constexpr double kFarAway = 1e9;

}  // namespace

ClipPlane::ClipPlane() : mPlane(vtkSmartPointer<vtkPlane>::New()), mPlanes(vtkSmartPointer<vtkPlaneCollection>::New())
{
    mPlanes->AddItem(mPlane);
    update();
}

ClipPlane::~ClipPlane() = default;

vtkPlaneCollection* ClipPlane::planes() const { return mPlanes; }

void ClipPlane::setAxis(ClipAxis axis, const glm::dvec3& viewDirection, const glm::dvec3& through)
{
    mAxis = axis;
    if (axis == ClipAxis::X) mNormal = {1.0, 0.0, 0.0};
    if (axis == ClipAxis::Y) mNormal = {0.0, 1.0, 0.0};
    if (axis == ClipAxis::Z) mNormal = {0.0, 0.0, 1.0};
    if (axis == ClipAxis::View) mNormal = -glm::normalize(viewDirection);  // the near side hides
    if (axis != ClipAxis::Off) mOffset = glm::dot(mNormal, through);
    update();
}

void ClipPlane::setOffset(double offset)
{
    mOffset = offset;
    update();
}

void ClipPlane::setFlipped(bool flipped)
{
    mFlipped = flipped;
    update();
}

std::optional<SectionPlane> ClipPlane::plane() const
{
    if (mAxis == ClipAxis::Off) return std::nullopt;
    const glm::dvec3 n = mFlipped ? -mNormal : mNormal;
    const glm::dvec3 o = mNormal * mOffset;
    return SectionPlane{{o.x, o.y, o.z}, {n.x, n.y, n.z}};
}

bool ClipPlane::hides(const glm::dvec3& world) const
{
    const std::optional<SectionPlane> p = plane();
    return p && (openvdb::Vec3d(world.x, world.y, world.z) - p->origin).dot(p->normal) > 0.0;
}

void ClipPlane::update()
{
    // VTK keeps the side its normal points to: the opposite of the hidden one.
    if (const std::optional<SectionPlane> p = plane()) {
        mPlane->SetOrigin(p->origin.x(), p->origin.y(), p->origin.z());
        mPlane->SetNormal(-p->normal.x(), -p->normal.y(), -p->normal.z());
    } else {
        mPlane->SetOrigin(0.0, 0.0, -kFarAway);
        mPlane->SetNormal(0.0, 0.0, 1.0);
    }
    ++mRevision;
}

}  // namespace sculpt::ui
