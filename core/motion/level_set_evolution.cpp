// SPDX-License-Identifier: Apache-2.0
#include "core/motion/level_set_evolution.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/central_difference.h"
#include "core/field/dense_gather.h"
#include "core/field/mean_curvature.h"
#include "core/field/surface_mask.h"
#include "core/mesh/field_measures.h"
#include "core/motion/volume_estimate.h"

#include <openvdb/math/FiniteDifference.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetTracker.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;
using LeafValues = std::array<float, LeafT::SIZE>;
constexpr int kApron = 3;  // WENO5 reads three voxels on each side
constexpr int kDim = int(LeafT::DIM) + 2 * kApron;

/// A leaf and its apron, densely: at(x, y, z) for leaf-local x, y, z in [-3, 10].
struct LeafStencil {
    std::array<float, kDim * kDim * kDim> v;
    float at(int x, int y, int z) const { return v[denseIndex(kDim, kDim, x + kApron, y + kApron, z + kApron)]; }
    void gather(const openvdb::FloatTree& tree, const openvdb::Coord& origin)
    {
        gatherDense(tree, openvdb::CoordBBox(origin.offsetBy(-kApron), origin.offsetBy(LeafT::DIM - 1 + kApron)),
                    v.data());
    }
};

/// What every voxel of one step needs to know, fixed for the step.
struct StepConstants {
    double h, invH;
    GradientScheme scheme;
    const openvdb::FloatTree* target = nullptr;
    float alpha = 0.0f, clampWorld = 0.0f;
    bool matchTargetValues = false;
    double beta = 0.0;
    std::optional<FalloffBall> smoothWeight;
    bool firstOrderTime = false;
    double uniformSpeed = 0.0;  // the offset term
    const openvdb::math::Transform* xform;

    /// True if nothing can move in the leaf: only a weighted smoothing acts, and its ball
    /// misses the leaf (a smoothing brush on a patch then costs its ball, not the patch).
    bool leafIsStill(const openvdb::Coord& origin) const
    {
        if (!smoothWeight || target || uniformSpeed != 0.0) return false;
        const openvdb::Vec3d centre = xform->worldToIndex(smoothWeight->centreWorld);
        openvdb::Vec3d nearest;
        for (int a = 0; a < 3; ++a) nearest[a] = std::clamp(centre[a], double(origin[a]), double(origin[a] + 7));
        return (nearest - centre).length() * h > smoothWeight->radiusWorld;
    }
};

/// One-sided differences along `axis` at (x, y, z): minus and plus.
void oneSided(const LeafStencil& s, int x, int y, int z, int axis, GradientScheme scheme, double invH, double& minus,
              double& plus)
{
    auto f = [&](int k) { return s.at(x + (axis == 0) * k, y + (axis == 1) * k, z + (axis == 2) * k); };
    if (scheme == GradientScheme::FirstOrder) {
        minus = (f(0) - f(-1)) * invH;
        plus = (f(1) - f(0)) * invH;
        return;
    }
    // Slopes, not differences: WENO5's smoothness epsilon assumes values of order one.
    double d[6];
    for (int k = 0; k < 6; ++k) d[k] = (f(k - 2) - f(k - 3)) * invH;
    minus = openvdb::math::WENO5(d[0], d[1], d[2], d[3], d[4]);
    plus = openvdb::math::WENO5(d[5], d[4], d[3], d[2], d[1]);
}

/// The right-hand side dphi/dt at one voxel.
class VoxelRate {
public:
    explicit VoxelRate(const StepConstants& constants) : mC(constants)
    {
        if (mC.target) mTarget.emplace(*mC.target);
    }

    double operator()(const LeafStencil& s, int x, int y, int z, const openvdb::Coord& ijk)
    {
        double speed = mC.uniformSpeed;
        if (mTarget) speed += targetSpeed(s, x, y, z, ijk);
        double rate = 0.0;
        if (speed != 0.0) {
            openvdb::Vec3d minus, plus;
            for (int axis = 0; axis < 3; ++axis)
                oneSided(s, x, y, z, axis, mC.scheme, mC.invH, minus[axis], plus[axis]);
            rate -= speed * std::sqrt(openvdb::math::GodunovsNormSqrd(speed > 0.0, minus, plus));
        }
        if (mC.beta > 0.0) {
            const double weight = mC.smoothWeight ? mC.smoothWeight->weightAt(mC.xform->indexToWorld(ijk)) : 1.0;
            if (weight > 0.0)
                rate += mC.beta * weight *
                        curvatureNormGrad([&](int i, int j, int k) { return s.at(i, j, k); }, x, y, z, mC.invH);
        }
        return rate;
    }

private:
    /// The target's speed taken at the voxel's closest surface point x - phi n, not at the
    /// voxel: every level set then moves with the surface (a cheap velocity extension), so the
    /// band stays a distance field instead of bunching up where the speed varies.
    double targetSpeed(const LeafStencil& s, int x, int y, int z, const openvdb::Coord& ijk)
    {
        const double towards =
            mC.matchTargetValues ? double(mTarget->getValue(ijk)) - s.at(x, y, z) : targetAtFoot(s, x, y, z, ijk);
        const double clamped = std::clamp(towards, double(-mC.clampWorld), double(mC.clampWorld));
        if (std::abs(s.at(x, y, z)) < mC.h) mFastestTarget = std::max(mFastestTarget, std::abs(clamped));
        return -mC.alpha * clamped;
    }

    double targetAtFoot(const LeafStencil& s, int x, int y, int z, const openvdb::Coord& ijk)
    {
        const openvdb::Vec3d foot = closestSurfacePoint(
            ijk.asVec3d(), s.at(x, y, z),
            centralDifference([&s](int i, int j, int k) { return s.at(i, j, k); }, x, y, z), mC.invH);
        return openvdb::tools::BoxSampler::sample(*mTarget, foot);
    }

public:
    /// Largest |clamped phi_T| read so far within a voxel of the surface: how fast the target
    /// term actually moved the surface.
    double fastestTarget() const { return mFastestTarget; }

private:
    const StepConstants& mC;
    std::optional<openvdb::tree::ValueAccessor<const openvdb::FloatTree>> mTarget;
    double mFastestTarget = 0.0;
};

/// One explicit Euler stage over every leaf: out[i] = phi + dt * rate (inactive voxels kept).
/// Returns the largest |clamped phi_T| the stage read near the surface (0 without a target).
double eulerStage(const openvdb::FloatTree& tree, const std::vector<LeafT*>& leaves, const StepConstants& c, double dt,
                  std::vector<LeafValues>& out)
{
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, leaves.size()), 0.0,
        [&](const tbb::blocked_range<size_t>& r, double fastest) {
            LeafStencil stencil;
            VoxelRate rate(c);
            for (size_t i = r.begin(); i < r.end(); ++i) {
                const LeafT& leaf = *leaves[i];
                std::copy(leaf.buffer().data(), leaf.buffer().data() + LeafT::SIZE, out[i].begin());
                if (leaf.isEmpty()) continue;
                stencil.gather(tree, leaf.origin());
                for (auto it = leaf.cbeginValueOn(); it; ++it) {
                    const openvdb::Coord local = it.getCoord() - leaf.origin();
                    out[i][it.pos()] = float(*it + dt * rate(stencil, local.x(), local.y(), local.z(), it.getCoord()));
                }
            }
            return std::max(fastest, rate.fastestTarget());
        },
        [](double a, double b) { return std::max(a, b); });
}

void writeLeaves(const std::vector<LeafT*>& leaves, const std::vector<LeafValues>& values, float background)
{
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size()), [&](const auto& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
            float* dst = leaves[i]->buffer().data();
            for (size_t k = 0; k < LeafT::SIZE; ++k) dst[k] = std::clamp(values[i][k], -background, background);
        }
    });
}

std::vector<LeafT*> leafList(openvdb::FloatTree& tree)
{
    std::vector<LeafT*> leaves;
    leaves.reserve(tree.leafCount());
    for (auto it = tree.beginLeaf(); it; ++it) leaves.push_back(it.getLeaf());
    return leaves;
}

void validateTerms(const MotionTerms& t, const FieldImage& field)
{
    auto finiteNonNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
    if (t.smooth && !finiteNonNegative(t.smooth->beta)) throw InputError("smoothing coefficient must be >= 0");
    if (t.target) {
        if (!t.target->target) throw InputError("no target shape given");
        if (!finiteNonNegative(t.target->alpha)) throw InputError("target speed must be >= 0");
        const double targetH = t.target->target->transform().voxelSize()[0];
        if (std::abs(targetH - field.voxelSize()) > 1e-9 * field.voxelSize()) {
            throw InputError("the target's voxel size " + formatNumber(targetH) + " differs from " +
                             formatNumber(field.voxelSize()) + "; resample it first");
        }
    }
    if (t.uniform && !std::isfinite(t.uniform->speedWorld)) throw InputError("offset speed must be finite");
    if (t.volume && !(finiteNonNegative(t.volume->targetVolume) && finiteNonNegative(t.volume->gamma))) {
        throw InputError("volume control needs a non-negative target volume and gain");
    }
}

/// One TVD-RK2 (Heun) step over every leaf of `grid`; returns the largest |clamped phi_T| read
/// near the surface.
double rk2Step(openvdb::FloatGrid& grid, const StepConstants& c, double dt)
{
    auto& tree = grid.tree();
    auto leaves = leafList(tree);
    // Leaves that cannot move are neither copied nor written (a brush on a patch).
    leaves.erase(
        std::remove_if(leaves.begin(), leaves.end(), [&](const LeafT* leaf) { return c.leafIsStill(leaf->origin()); }),
        leaves.end());
    if (c.firstOrderTime) {
        std::vector<LeafValues> next(leaves.size());
        const double fastest = eulerStage(tree, leaves, c, dt, next);
        writeLeaves(leaves, next, grid.background());
        return fastest;
    }
    std::vector<LeafValues> phi0(leaves.size()), stage(leaves.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size()), [&](const auto& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
            std::copy(leaves[i]->buffer().data(), leaves[i]->buffer().data() + LeafT::SIZE, phi0[i].begin());
        }
    });
    double fastest = eulerStage(tree, leaves, c, dt, stage);
    writeLeaves(leaves, stage, grid.background());
    fastest = std::max(fastest, eulerStage(tree, leaves, c, dt, stage));
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size()), [&](const auto& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
            for (size_t k = 0; k < LeafT::SIZE; ++k) stage[i][k] = 0.5f * (phi0[i][k] + stage[i][k]);
        }
    });
    writeLeaves(leaves, stage, grid.background());
    return fastest;
}

void redistanceGrid(openvdb::FloatGrid& grid, const EvolutionOptions& o)
{
    openvdb::tools::LevelSetTracker<openvdb::FloatGrid> tracker(grid);
    tracker.setSpatialScheme(o.scheme == GradientScheme::Weno5 ? openvdb::math::HJWENO5_BIAS
                                                               : openvdb::math::FIRST_BIAS);
    tracker.setTemporalScheme(openvdb::math::TVD_RK1);
    tracker.setNormCount(o.normalizeIterations);
    tracker.track();
}

}  // namespace

LevelSetEvolution::LevelSetEvolution(FieldImage& field, MotionTerms terms, EvolutionOptions options)
    : mField(field), mTerms(std::move(terms)), mOptions(options)
{
    validateTerms(mTerms, field);
    if (mTerms.target && mTerms.target->clampWorld <= 0.0) {
        mTerms.target->clampWorld = mTerms.target->target->background();
    }
    if (mTerms.target) mTargetReach = mTerms.target->clampWorld;
    if (!(mOptions.cfl > 0.0 && mOptions.cfl <= 1.0)) throw InputError("CFL number must be in (0, 1]");
}

double LevelSetEvolution::maxAdvectionSpeed() const
{
    double speed = 0.0;
    if (mTerms.target) speed += mTerms.target->alpha * mTargetReach;
    if (mTerms.uniform) speed += std::abs(mTerms.uniform->speedWorld);
    return speed;
}

double LevelSetEvolution::stableTimeStep() const
{
    const double h = mField.voxelSize();
    double dt = std::numeric_limits<double>::infinity();
    const double speed = maxAdvectionSpeed();
    if (speed > 0.0) dt = mOptions.cfl * h / speed;
    if (mTerms.smooth && mTerms.smooth->beta > 0.0) dt = std::min(dt, h * h / (6.0 * mTerms.smooth->beta));
    return dt;
}

double LevelSetEvolution::step(double maxDt)
{
    const double dt = std::min(maxDt, stableTimeStep());
    if (!std::isfinite(dt) || dt <= 0.0) return 0.0;  // no term moves anything
    heldByMask([&] {
        applyStep(dt);
        if (mTerms.volume) correctVolume();
    });
    mTime += dt;
    ++mSteps;
    return dt;
}

template <typename Edit>
void LevelSetEvolution::heldByMask(const Edit& edit)
{
    if (!mField.mask()) return edit();
    const openvdb::FloatGrid::ConstPtr before = mField.grid().deepCopy();
    edit();
    keepMasked(mField, *before);
}

void LevelSetEvolution::calibrateVolume()
{
    mVolumeBias = meshVolumeArea(mField).volume - estimateVolumeArea(mField.grid()).volume;
    mCalibratedAt = mSteps;
}

void LevelSetEvolution::correctVolume()
{
    constexpr int kCalibrationSteps = 10;
    if (mCalibratedAt < 0 || mSteps - mCalibratedAt >= kCalibrationSteps) calibrateVolume();
    const auto [estimate, area] = estimateVolumeArea(mField.grid());
    if (!(area > 0.0)) return;
    const double budget = mOptions.cfl * mField.voxelSize();
    const double volume = estimate + mVolumeBias;
    offsetValues(std::clamp(mTerms.volume->gamma * (mTerms.volume->targetVolume - volume) / area, -budget, budget));
}

void LevelSetEvolution::settleVolume()
{
    if (!mTerms.volume) return;
    for (int i = 0; i < 4; ++i) {
        const MeshVolumeArea now = meshVolumeArea(mField);
        const double error = mTerms.volume->targetVolume - now.volume;
        if (!(now.area > 0.0) || std::abs(error) <= 1e-4 * std::abs(mTerms.volume->targetVolume)) break;
        heldByMask([&] { offsetValues(std::clamp(error / now.area, -mField.voxelSize(), mField.voxelSize())); });
    }
    mCalibratedAt = -1;
}

void LevelSetEvolution::offsetValues(double displacement)
{
    openvdb::FloatGrid& grid = mField.mutableGrid();
    const float background = grid.background();
    const auto leaves = leafList(grid.tree());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size()), [&](const auto& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
            for (auto it = leaves[i]->beginValueOn(); it; ++it) {
                it.setValue(std::clamp(float(*it - displacement), -background, background));
            }
        }
    });
    mMovedSinceRedistance += std::abs(displacement);
    mField.markDirty(mField.allLeaves());  // every voxel moved: the mesher must see them all
}

void LevelSetEvolution::applyStep(double dt)
{
    openvdb::FloatGrid& grid = mField.mutableGrid();
    StepConstants c;
    c.h = mField.voxelSize();
    c.invH = 1.0 / c.h;
    c.scheme = mOptions.scheme;
    c.firstOrderTime = mOptions.firstOrderTime;
    if (mTerms.target) {
        c.target = &mTerms.target->target->tree();
        c.alpha = float(mTerms.target->alpha);
        c.clampWorld = float(mTargetReach);
        c.matchTargetValues = mTerms.target->matchValues;
    }
    c.beta = mTerms.smooth ? mTerms.smooth->beta : 0.0;
    if (mTerms.smooth) c.smoothWeight = mTerms.smooth->weight;
    c.uniformSpeed = mTerms.uniform ? mTerms.uniform->speedWorld : 0.0;
    c.xform = &grid.transform();

    // Every level set in the band, not only the surface, moves at up to max|F_adv|; where the
    // speed varies (a target, a brush) they bunch up, so rebuild before any may have moved
    // redistanceAfterMovingVoxels. Curvature flow diffuses the band's edge inwards by sqrt(2 beta t): rebuild
    // before that travels half a voxel too.
    mMovedSinceRedistance += maxAdvectionSpeed() * dt;
    mDiffusedSinceRedistance += c.beta * dt;
    const auto redistanceDue = [&] {
        return mMovedSinceRedistance >= mOptions.redistanceAfterMovingVoxels * c.h ||
               mDiffusedSinceRedistance >= mOptions.redistanceAfterDiffusingVoxels2 * c.h * c.h;
    };
    DirtyRegion touched = mField.allLeaves();
    updateTargetReach(rk2Step(grid, c, dt));
    if (redistanceDue()) {
        mDiffusedSinceRedistance = 0.0;
        redistanceGrid(grid, mOptions);
        mMovedSinceRedistance = 0.0;
        touched.merge(mField.allLeaves());
    }
    mField.markDirty(touched);
}

void LevelSetEvolution::updateTargetReach(double fastest)
{
    // Within a step the surface moves at most cfl h (and the volume control as much again),
    // and phi_T is 1-Lipschitz: a voxel more than the fastest reading near the surface bounds
    // the surface's next speed. Voxels deeper in the band are clamped to the same reach (their
    // foot points are less sure), so the CFL limit holds everywhere.
    if (mTerms.target) mTargetReach = std::min(mTerms.target->clampWorld, fastest + mField.voxelSize());
}

void LevelSetEvolution::redistance()
{
    heldByMask([&] { redistanceGrid(mField.mutableGrid(), mOptions); });
    mMovedSinceRedistance = 0.0;
    mDiffusedSinceRedistance = 0.0;
    mField.markDirty(mField.allLeaves());
}

void LevelSetEvolution::advance(double duration)
{
    const double end = mTime + duration;
    while (mTime < end) {
        if (step(end - mTime) <= 0.0) break;
    }
}

}  // namespace sculpt
