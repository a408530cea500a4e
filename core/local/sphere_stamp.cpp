// SPDX-License-Identifier: Apache-2.0
#include "core/local/sphere_stamp.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/band_rule.h"

#include <cmath>

namespace sculpt {

DirtyRegion stampSphere(FieldImage& field, const openvdb::Vec3d& centreWorld, double radiusWorld, CsgMode mode)
{
    if (!(radiusWorld > 0.0) || !std::isfinite(radiusWorld)) {
        throw InputError("stamp radius must be a positive number (got " + formatNumber(radiusWorld) + ")");
    }
    if (!std::isfinite(centreWorld.lengthSqr())) throw InputError("stamp centre is not finite");

    openvdb::FloatGrid& grid = field.mutableGrid();
    const float background = grid.background();
    const double reach = radiusWorld + background;
    const auto& xform = grid.transform();
    const openvdb::Coord lo = xform.worldToIndexCellCentered(centreWorld - openvdb::Vec3d(reach));
    const openvdb::Coord hi = xform.worldToIndexCellCentered(centreWorld + openvdb::Vec3d(reach));

    DirtyRegion touched;
    auto acc = grid.getAccessor();
    for (int x = lo.x(); x <= hi.x(); ++x) {
        for (int y = lo.y(); y <= hi.y(); ++y) {
            for (int z = lo.z(); z <= hi.z(); ++z) {
                const openvdb::Coord ijk(x, y, z);
                const double ball = (xform.indexToWorld(ijk) - centreWorld).length() - radiusWorld;
                const float old = acc.getValue(ijk);
                const float value = mode == CsgMode::Add ? std::min(old, float(ball)) : std::max(old, float(-ball));
                if (value == old) continue;
                setBandValue(acc, ijk, toBand(value, background));
                touched.addVoxel(ijk);
            }
        }
    }
    field.markDirty(touched);
    return touched;
}

}  // namespace sculpt
