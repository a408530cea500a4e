// SPDX-License-Identifier: Apache-2.0
#include "core/motion/shape_distance.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

using ConstLeafRange = openvdb::tree::LeafManager<const openvdb::FloatTree>::LeafRange;

struct DistanceTally {
    double max = 0.0, sum = 0.0, maxResolved = 0.0;
    double count = 0.0, resolved = 0.0;
    void add(double d, bool isResolved)
    {
        max = std::max(max, d);
        sum += d;
        count += 1.0;
        if (isResolved) {
            maxResolved = std::max(maxResolved, d);
            resolved += 1.0;
        }
    }
    DistanceTally merged(const DistanceTally& o) const
    {
        return {std::max(max, o.max), sum + o.sum, std::max(maxResolved, o.maxResolved), count + o.count,
                resolved + o.resolved};
    }
    ShapeDistance distance() const
    {
        return {max, count > 0.0 ? sum / count : 0.0, maxResolved, count > 0.0 ? resolved / count : 1.0};
    }
};

/// Samples a plain grid trilinearly.
class GridSampler {
public:
    explicit GridSampler(const openvdb::FloatGrid& grid) : mAcc(grid.getConstAccessor()) {}
    double at(const openvdb::Vec3d& p) { return openvdb::tools::BoxSampler::sample(mAcc, p); }

private:
    openvdb::FloatGrid::ConstAccessor mAcc;
};

/// Tells whether the reference shape is resolvable near a point (shape_distance.h).
class Resolvability {
public:
    explicit Resolvability(const openvdb::FloatGrid& reference)
        : mPhi(reference), mH(reference.voxelSize()[0]), mHalfWidth(reference.background())
    {}

    bool near(const openvdb::Vec3d& p)
    {
        constexpr double kDepthVoxels = 1.5, kGrowth = 0.8;
        const double phi = mPhi.at(p);
        if (std::abs(phi) >= 0.99 * mHalfWidth) return true;  // far from the reference: still travelling
        openvdb::Vec3d gradient;
        for (int axis = 0; axis < 3; ++axis) {
            openvdb::Vec3d e(0.0);
            e[axis] = 1.0;
            gradient[axis] = mPhi.at(p + e) - mPhi.at(p - e);
        }
        if (gradient.length() < 1e-12) return false;
        const openvdb::Vec3d n = gradient.unit();
        const openvdb::Vec3d foot = p - n * (phi / mH);
        return mPhi.at(foot - kDepthVoxels * n) <= -kGrowth * kDepthVoxels * mH &&
               mPhi.at(foot + kDepthVoxels * n) >= kGrowth * kDepthVoxels * mH;
    }

private:
    GridSampler mPhi;
    double mH, mHalfWidth;
};

/// Tallies |to| at every crossing of `from`'s zero set with a grid edge from an inside voxel;
/// MakeSampler() gives each thread its sampler of `to`.
template <typename MakeSampler>
DistanceTally tallyCrossings(const openvdb::FloatGrid& from, const MakeSampler& makeSampler,
                             const openvdb::FloatGrid& reference)
{
    openvdb::tree::LeafManager<const openvdb::FloatTree> leaves(from.tree());
    return tbb::parallel_reduce(
        leaves.leafRange(), DistanceTally{},
        [&](const ConstLeafRange& r, DistanceTally tally) {
            auto acc = from.getConstAccessor();
            auto to = makeSampler();
            Resolvability resolvable(reference);
            for (auto leaf = r.begin(); leaf; ++leaf) {
                for (auto it = leaf->cbeginValueOn(); it; ++it) {
                    if (*it >= 0.0f) continue;
                    for (int axis = 0; axis < 3; ++axis) {
                        for (int side : {-1, 1}) {
                            openvdb::Coord n = it.getCoord();
                            n[axis] += side;
                            const float outside = acc.getValue(n);
                            if (outside < 0.0f) continue;
                            openvdb::Vec3d p = it.getCoord().asVec3d();
                            p[axis] += side * double(*it) / (double(*it) - double(outside));
                            tally.add(std::abs(to.at(p)), resolvable.near(p));
                        }
                    }
                }
            }
            return tally;
        },
        [](const DistanceTally& a, const DistanceTally& b) { return a.merged(b); });
}

DistanceTally tallyTo(const openvdb::FloatGrid& from, const openvdb::FloatGrid& to, const openvdb::FloatGrid& reference)
{
    return tallyCrossings(
        from, [&] { return GridSampler(to); }, reference);
}

DistanceTally tallyTo(const openvdb::FloatGrid& from, const WideDistance& to, const openvdb::FloatGrid& reference)
{
    return tallyCrossings(
        from, [&] { return WideDistance::Sampler(to); }, reference);
}

}  // namespace

ShapeDistance surfaceToField(const openvdb::FloatGrid& from, const openvdb::FloatGrid& to)
{
    return tallyTo(from, to, to).distance();
}

ShapeDistance surfaceToField(const openvdb::FloatGrid& from, const WideDistance& to)
{
    return tallyTo(from, to, to.band()).distance();
}

ShapeDistance twoSidedDistance(const openvdb::FloatGrid& a, const openvdb::FloatGrid& b, const WideDistance& bDistance)
{
    return tallyTo(a, bDistance, b).merged(tallyTo(b, a, b)).distance();
}

ShapeDistance twoSidedDistance(const openvdb::FloatGrid& a, const WideDistance& aDistance, const openvdb::FloatGrid& b,
                               const WideDistance& bDistance)
{
    return tallyTo(a, bDistance, b).merged(tallyTo(b, aDistance, b)).distance();
}

}  // namespace sculpt
