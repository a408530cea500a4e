#include "core/motion/morph.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/local/speck_removal.h"
#include "core/mesh/field_measures.h"
#include "core/motion/level_set_evolution.h"

#include <openvdb/tools/GridTransformer.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <limits>

namespace sculpt {

namespace {

using ConstLeafRange = openvdb::tree::LeafManager<const openvdb::FloatTree>::LeafRange;

/// Centre of the interior (voxels and tiles with negative values), world space.
openvdb::Vec3d interiorCentroid(const openvdb::FloatGrid& grid)
{
    openvdb::Vec3d sum(0.0);
    double count = 0.0;
    for (auto it = grid.tree().cbeginValueAll(); it; ++it) {
        if (*it >= 0.0f) continue;
        const openvdb::CoordBBox box = it.getBoundingBox();
        const double n = double(box.volume());
        sum += n * (box.min().asVec3d() + box.max().asVec3d()) * 0.5;
        count += n;
    }
    if (count == 0.0) throw InputError("the shape has no interior");
    return grid.transform().indexToWorld(sum / count);
}

/// True if some voxel of `a` near its surface lies inside both shapes.
bool insideBoth(const openvdb::FloatGrid& a, const openvdb::FloatGrid& b)
{
    auto acc = b.getConstAccessor();
    for (auto it = a.cbeginValueOn(); it; ++it) {
        if (*it < 0.0f && acc.getValue(it.getCoord()) < 0.0f) return true;
    }
    return false;
}

/// The source in the target's voxels, translated by `shift` (world units).
FieldImage resampleInto(const FieldImage& source, const FieldImage& target, const openvdb::Vec3d& shift)
{
    if (shift == openvdb::Vec3d(0.0) && source.grid().transform() == target.grid().transform()) {
        return FieldImage(source.grid().deepCopy(), source.units());
    }
    auto moved = source.grid().deepCopy();
    moved->transform().postTranslate(shift);
    auto out = makeLevelSetGrid(target.grid().transform(), target.grid().background());
    out->setName(source.grid().getName());
    openvdb::tools::resampleToMatch<openvdb::tools::BoxSampler>(*moved, *out);
    return FieldImage(out, source.units());
}

FieldImage prepareSource(const FieldImage& source, const FieldImage& target, bool align, openvdb::Vec3d& shift)
{
    shift = align ? interiorCentroid(target.grid()) - interiorCentroid(source.grid()) : openvdb::Vec3d(0.0);
    FieldImage prepared = resampleInto(source, target, shift);
    if (!insideBoth(prepared.grid(), target.grid()) && !insideBoth(target.grid(), prepared.grid())) {
        throw InputError("the source and target shapes do not overlap, so the source cannot follow the "
                         "target; translate the source onto the target first, aligning their centroids",
                         Remedy::AlignShapes);
    }
    return prepared;
}

MotionTerms targetTerms(const FieldImage& target)
{
    MotionTerms terms;
    terms.target = TargetTerm{target.gridPtr(), 1.0, 0.0};
    return terms;
}

/// Watches the distance to the target: converged below the tolerance, stalled when 40 steps
/// brought no 1% improvement (sharp corners stay a fraction of a voxel off).
class ConvergenceWatch {
public:
    explicit ConvergenceWatch(double tolerance) : mTolerance(tolerance) {}

    /// Measures every 4th step; true when the morph should stop.
    bool done(const FieldImage& field, const FieldImage& target, int step)
    {
        if (step % 4 != 0) return false;
        mLast = surfaceDistance(field, target);
        if (mLast < 0.99 * mBest) {
            mBest = mLast;
            mBestStep = step;
        }
        return mLast <= mTolerance || step - mBestStep >= 40;
    }
    double last() const { return mLast; }

private:
    double mTolerance;
    double mBest = std::numeric_limits<double>::infinity();
    double mLast = std::numeric_limits<double>::infinity();
    int mBestStep = 0;
};

/// First pass: how long the plain target-following motion takes to converge.
double convergenceTime(const FieldImage& start, const FieldImage& target, const MorphOptions& o, double tolerance,
                       const Progress& progress)
{
    FieldImage field(start.grid().deepCopy());
    LevelSetEvolution evolution(field, targetTerms(target));
    ConvergenceWatch watch(tolerance);
    const double d0 = std::max(surfaceDistance(field, target), 2.0 * tolerance);
    while (evolution.stepCount() < o.maxSteps && !watch.done(field, target, evolution.stepCount())) {
        evolution.step();
        const double d = std::max(watch.last(), tolerance);
        if (std::isfinite(d)) report(progress, 0.5 * std::clamp(std::log(d0 / d) / std::log(d0 / tolerance), 0.0, 1.0));
    }
    return evolution.time();
}

}  // namespace

double surfaceDistance(const FieldImage& field, const FieldImage& target)
{
    openvdb::tree::LeafManager<const openvdb::FloatTree> leaves(field.grid().tree());
    return tbb::parallel_reduce(
        leaves.leafRange(), 0.0,
        [&](const ConstLeafRange& r, double worst) {
            auto acc = field.grid().getConstAccessor();
            auto targetAcc = target.grid().getConstAccessor();
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
                            const double d = std::abs(openvdb::tools::BoxSampler::sample(targetAcc, p));
                            worst = std::max(worst, d);
                        }
                    }
                }
            }
            return worst;
        },
        [](double a, double b) { return std::max(a, b); });
}

MorphSummary morph(const FieldImage& source, const FieldImage& target, const MorphOptions& o,
                   const std::function<void(const MorphFrame&)>& onFrame, const Progress& progress)
{
    if (o.frames < 2) throw InputError("a morph needs at least 2 frames (got " + std::to_string(o.frames) + ")");
    if (!(o.toleranceVoxels > 0.0)) throw InputError("morph tolerance must be positive");
    MorphSummary summary;
    const FieldImage start = prepareSource(source, target, o.align, summary.translation);
    const double tolerance = o.toleranceVoxels * target.voxelSize();
    const double duration = convergenceTime(start, target, o, tolerance, progress);

    FieldImage field(start.grid().deepCopy(), source.units());
    MotionTerms terms = targetTerms(target);
    // Volumes are the meshes' (what a user measures on the exported frames).
    const double v0 = meshVolumeArea(field).volume;
    const double v1 = meshVolumeArea(target).volume;
    if (o.keepVolume) terms.volume = VolumeTerm{v0, 1.0};
    LevelSetEvolution evolution(field, terms);

    auto emit = [&](int index) {
        if (index > 0) {
            evolution.redistance();
            removeSpecks(field);
        }
        if (evolution.terms().volume) evolution.settleVolume();  // on the straight line
        const double volume = meshVolumeArea(field).volume;
        summary.frameVolumes.push_back(volume);
        onFrame(MorphFrame{index, evolution.time(), volume, field});
    };
    emit(0);
    for (int frame = 1; frame < o.frames; ++frame) {
        const double frameTime = duration * frame / (o.frames - 1);
        while (evolution.time() < frameTime && evolution.stepCount() < o.maxSteps) {
            const double dt = std::min(frameTime - evolution.time(), evolution.stableTimeStep());
            // The line ends on the target's volume at T; from there the shape converges onto the
            // target itself, which has that volume, so the control stops.
            auto& volume = evolution.terms().volume;
            if (volume && evolution.time() + dt < duration) {
                volume->targetVolume = v0 + (v1 - v0) * (evolution.time() + dt) / duration;
            } else {
                volume.reset();
            }
            evolution.step(dt);
            report(progress, 0.5 + 0.5 * evolution.time() / std::max(duration, 1e-30));
        }
        if (frame + 1 == o.frames) {  // the last frame waits until the surface stops improving
            ConvergenceWatch watch(0.0);
            while (evolution.stepCount() < o.maxSteps && !watch.done(field, target, evolution.stepCount())) {
                evolution.step();
            }
        }
        emit(frame);
    }
    summary.steps = evolution.stepCount();
    summary.duration = evolution.time();
    summary.finalDistanceWorld = surfaceDistance(field, target);
    summary.converged = summary.finalDistanceWorld <= tolerance;
    return summary;
}

}  // namespace sculpt
