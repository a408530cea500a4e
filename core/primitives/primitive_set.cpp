// SPDX-License-Identifier: Apache-2.0
#include "core/primitives/primitive_set.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sculpt {

std::string describePrimitive(int index, const std::string& name)
{
    return "primitive " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
}

PrimitiveSet::PrimitiveSet(std::vector<Primitive> primitives, double iso, bool useGraph)
    : mPrimitives(std::move(primitives)), mIso(iso), mUseGraph(useGraph)
{
    if (mPrimitives.empty()) throw InputError("the scene has no primitives");
    if (!(iso > 0.0) || !std::isfinite(iso))
        throw InputError("iso must be a positive number (got " + formatNumber(iso) + ")");
    const int count = int(mPrimitives.size());
    for (int i = 0; i < count; ++i) {
        Primitive& p = mPrimitives[size_t(i)];
        const std::string what = describePrimitive(i, p.name);
        p.skeleton.validate(what);
        if (!(p.kernel.radius > 0.0) || !std::isfinite(p.kernel.radius)) {
            throw InputError(what + ": radius must be a positive number (got " + formatNumber(p.kernel.radius) + ")");
        }
        if (!(p.kernel.strength > iso) || !std::isfinite(p.kernel.strength)) {
            throw InputError(what + ": strength " + formatNumber(p.kernel.strength) + " must exceed the iso-value " +
                             formatNumber(iso) + " or it has no surface");
        }
        for (int j : p.neighbours) {
            if (j < 0 || j >= count || j == i)
                throw InputError(what + ": neighbour " + std::to_string(j) + " names no other primitive");
        }
    }
    for (int i = 0; i < count; ++i) {  // blending is mutual
        for (int j : std::vector<int>(mPrimitives[size_t(i)].neighbours)) {
            auto& back = mPrimitives[size_t(j)].neighbours;
            if (std::find(back.begin(), back.end(), i) == back.end()) back.push_back(i);
        }
    }
}

double PrimitiveSet::field(const openvdb::Vec3d& p) const
{
    std::vector<int> all(mPrimitives.size());
    std::iota(all.begin(), all.end(), 0);
    return field(p, all);
}

double PrimitiveSet::field(const openvdb::Vec3d& p, const std::vector<int>& nearby) const
{
    if (!mUseGraph) {
        double sum = 0.0;
        for (int i : nearby) sum += mPrimitives[size_t(i)].kernel.value(mPrimitives[size_t(i)].skeleton.distance(p));
        return sum;
    }
    // Preponderant primitive, then its neighbours (their influence reaching p or not).
    int best = -1;
    double bestValue = 0.0;
    for (int i : nearby) {
        const double v = mPrimitives[size_t(i)].kernel.value(mPrimitives[size_t(i)].skeleton.distance(p));
        if (v > bestValue) best = i, bestValue = v;
    }
    if (best < 0) return 0.0;
    double sum = bestValue;
    for (int j : mPrimitives[size_t(best)].neighbours) {
        sum += mPrimitives[size_t(j)].kernel.value(mPrimitives[size_t(j)].skeleton.distance(p));
    }
    return sum;
}

openvdb::BBoxd PrimitiveSet::influence(int i) const
{
    openvdb::BBoxd box = mPrimitives[size_t(i)].skeleton.bounds();
    box.expand(mPrimitives[size_t(i)].kernel.radius);
    return box;
}

openvdb::BBoxd PrimitiveSet::influence() const
{
    openvdb::BBoxd box;
    for (int i = 0; i < int(mPrimitives.size()); ++i) box.expand(influence(i));
    return box;
}

PrimitiveSet PrimitiveSet::translated(const openvdb::Vec3d& offset) const
{
    PrimitiveSet moved = *this;
    for (Primitive& primitive : moved.mPrimitives) {
        for (openvdb::Vec3d& point : primitive.skeleton.points) point += offset;
    }
    return moved;
}

}  // namespace sculpt
