// SPDX-License-Identifier: Apache-2.0
#include "core/pieces/lattice_transfer.h"

#include <openvdb/tools/LevelSetRebuild.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <cmath>
#include <optional>

namespace sculpt {

namespace {

/// Source index space to target index space, as one affine matrix (row vectors).
openvdb::Mat4d indexToIndex(const FieldImage& source, const openvdb::Mat4d& toTarget, const FieldImage& target)
{
    const auto affine = [](const openvdb::math::Transform& t) { return t.baseMap()->getAffineMap()->getMat4(); };
    return affine(source.grid().transform()) * toTarget * affine(target.grid().transform()).inverse();
}

/// The whole-voxel offset `m` moves indices by, when it does nothing else.
std::optional<openvdb::Coord> wholeVoxelShift(const openvdb::Mat4d& m)
{
    if (!m.getMat3().eq(openvdb::math::Mat3d::identity(), 1e-9)) return std::nullopt;
    const openvdb::Vec3d t = m.getTranslation();
    const openvdb::Coord shift(openvdb::Coord::round(t));
    if (!(t - shift.asVec3d()).eq(openvdb::Vec3d(0.0), 1e-6)) return std::nullopt;
    return shift;
}

/// `source`'s voxels moved by whole voxels onto the target's transform: exact, no resampling.
FieldImage shifted(const FieldImage& source, const openvdb::Coord& shift, const FieldImage& target)
{
    openvdb::FloatGrid::Ptr moved = makeLevelSetGrid(target.grid().transform(), source.grid().background());
    auto out = moved->getAccessor();
    for (auto v = source.grid().cbeginValueOn(); v; ++v) out.setValue(v.getCoord() + shift, *v);
    openvdb::tools::signedFloodFill(moved->tree());  // the inside, from the band's signs
    return FieldImage(moved, target.units());
}

}  // namespace

FieldImage onLatticeOf(const FieldImage& source, const openvdb::Mat4d& sourcePlacement, const FieldImage& target,
                       const openvdb::Mat4d& targetPlacement, double halfWidthVoxels)
{
    const openvdb::Mat4d toTarget = sourcePlacement * targetPlacement.inverse();
    const bool sameLattice = toTarget.eq(openvdb::Mat4d::identity()) &&
                             source.grid().transform() == target.grid().transform() &&
                             std::abs(source.halfWidthVoxels() - halfWidthVoxels) < 1e-6;
    if (sameLattice) return source;
    if (std::abs(source.halfWidthVoxels() - halfWidthVoxels) < 1e-6) {
        if (const auto shift = wholeVoxelShift(indexToIndex(source, toTarget, target)))
            return shifted(source, *shift, target);
    }
    // A shallow copy (the tree is shared): only its transform changes.
    openvdb::FloatGrid::Ptr placed = openvdb::ConstPtrCast<openvdb::FloatGrid>(source.gridPtr())->copy();
    placed->setTransform(source.grid().transform().copy());
    placed->transform().postMult(toTarget);
    const float width = float(halfWidthVoxels);
    openvdb::FloatGrid::Ptr moved =
        openvdb::tools::levelSetRebuild(*placed, 0.0f, width, width, &target.grid().transform());
    moved->setName("");
    return FieldImage(moved, target.units());
}

}  // namespace sculpt
