// SPDX-License-Identifier: Apache-2.0
#include "core/field/field_image.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/grid_tiles.h"
#include "core/field/voxel_size.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sculpt {

openvdb::FloatGrid::Ptr makeLevelSetGrid(const openvdb::math::Transform& xform, float background)
{
    auto grid = openvdb::FloatGrid::create(background);
    grid->setTransform(xform.copy());
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->setName("surface");
    return grid;
}

void requireWithinModelExtent(const openvdb::BBoxd& world, double voxelSize, const std::string& what)
{
    double reach = 0.0;
    for (int a = 0; a < 3; ++a) reach = std::max({reach, std::abs(world.min()[a]), std::abs(world.max()[a])});
    reach /= voxelSize;
    if (!(reach <= double(kMaxIndexCoordinate))) {
        throw InputError(what + " reaches " + formatNumber(reach) + " voxels from the origin at voxel size " +
                             formatNumber(voxelSize) + ", beyond the largest model (" +
                             formatNumber(kMaxIndexCoordinate) +
                             "): move it nearer the origin, or choose a coarser voxel size",
                         Remedy::CoarserVoxelSize);
    }
}

openvdb::FloatGrid::Ptr makeLevelSetGrid(double voxelSize, double halfWidthVoxels)
{
    return makeLevelSetGrid(*voxelTransform(voxelSize), float(voxelSize * halfWidthVoxels));
}

namespace {

double uniformVoxelSize(const openvdb::math::Transform& transform)
{
    if (!transform.isLinear()) {
        throw InputError("the grid's transform is not linear (frustum grids cannot be sculpted)");
    }
    if (!transform.hasUniformScale()) {
        throw InputError("the grid's voxels are not cubes (non-uniform voxel size)");
    }
    return transform.voxelSize()[0];
}

}  // namespace

FieldImage::FieldImage(openvdb::FloatGrid::Ptr grid, std::string units)
    : mGrid(std::move(grid)), mUnits(std::move(units))
{
    if (!mGrid) throw InputError("no grid given");
    if (mGrid->getGridClass() != openvdb::GRID_LEVEL_SET) {
        throw InputError("grid '" + mGrid->getName() + "' is not a level set");
    }
    mVoxelSize = uniformVoxelSize(mGrid->transform());
    if (!(mVoxelSize > 0.0) || !std::isfinite(mVoxelSize)) {
        throw InputError("voxel size must be positive and finite");
    }
    if (!(mGrid->background() >= float(mVoxelSize))) {
        throw InputError("grid '" + mGrid->getName() + "' has a band narrower than one voxel (background " +
                         formatNumber(mGrid->background()) + ")");
    }
}

FieldImage FieldImage::deepCopy() const
{
    FieldImage copy(mGrid->deepCopy(), mUnits);
    if (mask()) copy.mMask = mMask->deepCopy();
    return copy;
}

openvdb::FloatGrid::Ptr makeMaskGrid(const openvdb::math::Transform& xform)
{
    auto mask = openvdb::FloatGrid::create(0.0f);
    mask->setTransform(xform.copy());
    mask->setGridClass(openvdb::GRID_FOG_VOLUME);
    mask->setName("mask");
    return mask;
}

openvdb::FloatGrid& FieldImage::mutableMask()
{
    if (!mMask) mMask = makeMaskGrid(mGrid->transform());
    return *mMask;
}

void FieldImage::setMask(openvdb::FloatGrid::Ptr mask)
{
    if (mask && mask->transform() != mGrid->transform())
        throw InputError("the mask '" + mask->getName() + "' is not on the surface's voxels (another transform)");
    mMask = std::move(mask);
}

void FieldImage::swapGrid(openvdb::FloatGrid::Ptr& other)
{
    if (!other || other->getGridClass() != openvdb::GRID_LEVEL_SET || other->transform() != mGrid->transform()) {
        throw InputError("a whole-model edit must keep the model's voxels (a level set on the same transform)");
    }
    markDirty(allLeaves());
    std::swap(mGrid, other);
    markDirty(allLeaves());
}

double FieldImage::halfWidthVoxels() const { return double(mGrid->background()) / mVoxelSize; }

DirtyRegion FieldImage::allLeaves() const
{
    DirtyRegion region;
    for (auto leaf = mGrid->tree().cbeginLeaf(); leaf; ++leaf) region.addVoxel(leaf->origin());
    return region;
}

DirtyRegion FieldImage::takeDirtyRegion() { return std::exchange(mDirty, DirtyRegion{}); }

bool FieldImage::enclosesSomething() const
{
    for (auto leaf = mGrid->tree().cbeginLeaf(); leaf; ++leaf) {
        const float* values = leaf->buffer().data();
        if (std::any_of(values, values + leaf->SIZE, [](float phi) { return phi < 0.0f; })) return true;
    }
    bool inside = false;
    forEachTileOffBackground(mGrid->tree(),
                             [&](const openvdb::CoordBBox&, float value, bool) { inside |= value < 0.0f; });
    return inside;
}

}  // namespace sculpt
