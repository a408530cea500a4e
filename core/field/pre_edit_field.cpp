// SPDX-License-Identifier: Apache-2.0
#include "core/field/pre_edit_field.h"

#include "core/field/central_difference.h"

#include <cmath>

namespace sculpt {

PreEditField::PreEditField(const FieldImage& field, const LeafJournal* edits)
    : mField(field), mEdits(edits && !edits->empty() ? edits : nullptr), mAccessor(field.grid().getConstAccessor())
{}

float PreEditField::value(const openvdb::Coord& ijk) const
{
    if (mEdits) {
        const openvdb::Coord origin = ijk & ~openvdb::Int32(openvdb::FloatTree::LeafNodeType::DIM - 1);
        if (origin != mLeafOrigin) {
            mLeafOrigin = origin;
            mSaved = mEdits->saved(origin);
        }
        if (mSaved) return mSaved->leaf ? mSaved->leaf->getValue(ijk) : mSaved->value;
    }
    return mAccessor.getValue(ijk);
}

double PreEditField::sample(const openvdb::Vec3d& index) const
{
    const openvdb::Vec3d floor(std::floor(index.x()), std::floor(index.y()), std::floor(index.z()));
    const openvdb::Vec3d f = index - floor;
    const openvdb::Coord base(int(floor.x()), int(floor.y()), int(floor.z()));
    double result = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
        const double weight = (dx ? f.x() : 1.0 - f.x()) * (dy ? f.y() : 1.0 - f.y()) * (dz ? f.z() : 1.0 - f.z());
        if (weight > 0.0) result += weight * double(value(base.offsetBy(dx, dy, dz)));
    }
    return result;
}

openvdb::Vec3d PreEditField::gradient(const openvdb::Vec3d& index) const
{
    return centralDifference([&](int x, int y, int z) { return sample(index + openvdb::Vec3d(x, y, z) * 0.5); }, 0, 0,
                             0);
}

}  // namespace sculpt
