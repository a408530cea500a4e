// SPDX-License-Identifier: Apache-2.0
#include "core/motion/morph.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/surface_mask.h"
#include "core/local/speck_removal.h"
#include "core/mesh/field_measures.h"
#include "core/motion/level_set_evolution.h"
#include "core/motion/wide_distance.h"

#include <openvdb/tools/GridTransformer.h>

#include <cmath>
#include <limits>
#include <optional>

namespace sculpt {

namespace {

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
        return source.deepCopy();
    }
    auto moved = source.grid().deepCopy();
    moved->transform().postTranslate(shift);
    auto out = makeLevelSetGrid(target.grid().transform(), target.grid().background());
    out->setName(source.grid().getName());
    openvdb::tools::resampleToMatch<openvdb::tools::BoxSampler>(*moved, *out);
    FieldImage resampled(out, source.units());
    if (source.mask()) {
        auto mask = source.mask()->deepCopy();
        mask->transform().postTranslate(shift);
        openvdb::tools::resampleToMatch<openvdb::tools::BoxSampler>(*mask, resampled.mutableMask());
    }
    return resampled;
}

/// A frame as the mask lets it be: the share of the way from `start` the mask holds kept back.
FieldImage heldByMask(const FieldImage& frame, const FieldImage& start)
{
    FieldImage held = frame.deepCopy();
    held.setMask(start.maskPtr());
    keepMasked(held, start.grid());
    return held;
}

}  // namespace

bool morphConverged(const ShapeDistance& d, double toleranceWorld, double voxelSize)
{
    return d.maxResolvedWorld <= toleranceWorld && d.maxWorld <= toleranceWorld + voxelSize;
}

FieldImage morphStart(const FieldImage& source, const FieldImage& target, bool align, openvdb::Vec3d& shift)
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

namespace {

MotionTerms targetTerms(const FieldImage& target)
{
    MotionTerms terms;
    terms.target = TargetTerm{target.gridPtr(), 1.0, 0.0};
    return terms;
}

/// The target and its distance widened over the source. The motion reads the band: its speed is
/// clamped to the band's half width anyway, and beyond the band only the sign matters. The
/// convergence measure reads the widened distance, so it sees far parts approach.
struct MorphTarget {
    const FieldImage& shape;
    WideDistance distance;
    ShapeDistance distanceFrom(const FieldImage& field) const
    {
        return twoSidedDistance(field.grid(), shape.grid(), distance);
    }
};

/// Watches the two-sided distance to the target: converged when morphConverged says so; stalled
/// when 40 steps brought no 1% fall of its mean
/// (thin parts and sharp edges stay a fraction of a voxel off). The mean keeps falling while
/// any part still travels, far or near.
class ConvergenceWatch {
public:
    explicit ConvergenceWatch(double tolerance) : mTolerance(tolerance) {}

    /// Measures every 4th step; true when the morph should stop.
    bool done(const FieldImage& field, const MorphTarget& target, int step)
    {
        if (step % 4 != 0) return false;
        mLast = target.distanceFrom(field);
        if (mLast.meanWorld < 0.99 * mBestMean) {
            mBestMean = mLast.meanWorld;
            mBestStep = step;
        }
        mStalled = step - mBestStep >= 40;
        return morphConverged(mLast, mTolerance, field.voxelSize()) || mStalled;
    }
    double lastMax() const { return mLast.maxResolvedWorld; }
    bool stalled() const { return mStalled; }

private:
    double mTolerance;
    double mBestMean = std::numeric_limits<double>::infinity();
    ShapeDistance mLast{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::infinity(), 0.0};
    int mBestStep = 0;
    bool mStalled = false;
};

/// States of the plain target-following motion, kept every few steps of the first pass, so the
/// second starts each frame from the latest state before it instead of from the source (without
/// volume control the two passes follow the same motion). At most 16 copies and 1 GiB, whatever
/// memory is free: where the second pass resumes decides the frames, which must not depend on
/// the machine. When full, every other one goes and the interval doubles.
class Checkpoints {
public:
    struct State {
        double time;
        openvdb::FloatGrid::ConstPtr grid;
    };

    /// Keeps nothing unless `wanted` (with volume control the second pass cannot use them).
    Checkpoints(const openvdb::FloatGrid& grid, bool wanted)
        : mCapacity(wanted ? std::min<std::uint64_t>(16, kBytes / std::max<std::uint64_t>(grid.memUsage(), 1)) : 0)
    {}

    void offer(const openvdb::FloatGrid& grid, double time, int step)
    {
        if (mCapacity < 2 || step % mEvery != 0) return;
        if (mKept.size() == mCapacity) {
            for (size_t i = 1; 2 * i < mKept.size(); ++i) mKept[i] = mKept[2 * i];
            mKept.resize((mKept.size() + 1) / 2);
            mEvery *= 2;
            if (step % mEvery != 0) return;
        }
        mKept.push_back({time, grid.deepCopy()});
    }

    /// The latest state at or before `time`, or nullptr.
    const State* latestAtOrBefore(double time) const
    {
        const State* found = nullptr;
        for (const State& s : mKept) {
            if (s.time <= time) found = &s;
        }
        return found;
    }

private:
    static constexpr std::uint64_t kBytes = std::uint64_t(1) << 30;
    std::uint64_t mCapacity;
    int mEvery = 8;
    std::vector<State> mKept;
};

struct FirstPass {
    double duration = 0.0;  ///< morph time T to convergence (or stall)
    int steps = 0;
    Checkpoints states;
};

/// First pass: how long the plain target-following motion takes to converge, and states along
/// the way (the last at T).
FirstPass convergenceTime(const FieldImage& start, const MorphTarget& target, const MorphOptions& o, double tolerance,
                          const Progress& progress)
{
    FieldImage field(start.grid().deepCopy());
    LevelSetEvolution evolution(field, targetTerms(target.shape));
    ConvergenceWatch watch(tolerance);
    FirstPass pass{0.0, 0, Checkpoints(field.grid(), !o.keepVolume)};
    const double d0 = std::max(target.distanceFrom(field).maxWorld, 2.0 * tolerance);
    while (evolution.stepCount() < o.maxSteps && !watch.done(field, target, evolution.stepCount())) {
        evolution.step();
        pass.states.offer(field.grid(), evolution.time(), evolution.stepCount());
        const double d = std::max(watch.lastMax(), tolerance);
        if (std::isfinite(d)) report(progress, std::clamp(std::log(d0 / d) / std::log(d0 / tolerance), 0.0, 1.0));
    }
    pass.duration = evolution.time();
    pass.steps = evolution.stepCount();
    pass.states.offer(field.grid(), pass.duration, 0);
    return pass;
}

/// The Hausdorff distance between the final surface and the target, both ways beyond the bands.
ShapeDistance finalDistance(const FieldImage& field, const MorphTarget& target)
{
    const WideDistance fieldDistance(field.gridPtr(), target.shape.grid());
    return twoSidedDistance(field.grid(), fieldDistance, target.shape.grid(), target.distance);
}

/// Progress of a part of the work: fractions [begin, end] of the whole.
Progress part(const Progress& progress, double begin, double end)
{
    if (!progress) return {};
    return [=](double f) { return progress(begin + (end - begin) * f); };
}

/// The last frame waits until the surface stops improving, or `steps` run out (`stop` says
/// which); progress is the share of those steps, so Esc is heard throughout.
void settle(LevelSetEvolution& evolution, const FieldImage& field, const MorphTarget& goal, int steps, MorphStop& stop,
            const Progress& progress, const std::function<void(const FieldImage&)>& onStep)
{
    ConvergenceWatch watch(0.0);
    const int first = evolution.stepCount();
    while (evolution.stepCount() - first < steps && !watch.done(field, goal, evolution.stepCount())) {
        evolution.step();
        if (onStep) onStep(field);
        report(progress, double(evolution.stepCount() - first) / steps);
    }
    stop = watch.stalled() ? MorphStop::Stalled : MorphStop::StepLimit;
}

}  // namespace

MorphSummary morph(const FieldImage& source, const FieldImage& target, const MorphOptions& o,
                   const std::function<void(const MorphFrame&)>& onFrame, const Progress& progress,
                   const std::function<void(const FieldImage&)>& onStep)
{
    const auto stepped = [&](const FieldImage& f) {
        if (onStep) onStep(f);
    };
    if (o.frames < 2 || o.frames > kMaxMorphFrames) {
        throw InputError("a morph writes 2 to " + std::to_string(kMaxMorphFrames) + " frames (got " +
                         std::to_string(o.frames) + ")");
    }
    if (!(o.toleranceVoxels > 0.0)) throw InputError("morph tolerance must be positive");
    MorphSummary summary;
    const FieldImage start = morphStart(source, target, o.align, summary.translation);
    const double tolerance = o.toleranceVoxels * target.voxelSize();
    const MorphTarget goal{target, WideDistance(target.gridPtr(), start.grid(), part(progress, 0.0, 0.05))};
    FirstPass first = convergenceTime(start, goal, o, tolerance, part(progress, 0.05, 0.5));
    const double duration = first.duration;

    FieldImage field(start.grid().deepCopy(), source.units());
    MotionTerms terms = targetTerms(target);
    // Volumes are the meshes' (what a user measures on the exported frames).
    const double v0 = meshVolumeArea(field).volume;
    const double v1 = meshVolumeArea(target).volume;
    if (o.keepVolume) terms.volume = VolumeTerm{v0, 1.0};
    std::optional<LevelSetEvolution> evolution(std::in_place, field, terms);
    double startTime = 0.0;  // morph time at which `evolution` started
    int steps = 0;           // of the evolutions before this one
    auto now = [&] { return startTime + evolution->time(); };
    auto secondPassSteps = [&] { return steps + evolution->stepCount(); };
    auto resumeFrom = [&](const Checkpoints::State& state) {
        steps += evolution->stepCount();
        field = FieldImage(state.grid->deepCopy(), source.units());
        evolution.emplace(field, terms);
        startTime = state.time;
        stepped(field);
    };

    auto emit = [&](int index) {
        if (index > 0) {
            evolution->redistance();
            removeSpecks(field);
        }
        if (evolution->terms().volume) evolution->settleVolume();  // on the straight line
        if (index > 0) stepped(field);
        std::optional<FieldImage> held;
        if (start.mask()) held.emplace(heldByMask(field, start));
        const FieldImage& shown = held ? *held : field;
        const double volume = meshVolumeArea(shown).volume;
        summary.frameVolumes.push_back(volume);
        onFrame(MorphFrame{index, now(), volume, shown});
    };
    emit(0);
    for (int frame = 1; frame < o.frames; ++frame) {
        const double frameTime = duration * frame / (o.frames - 1);
        const Checkpoints::State* state = first.states.latestAtOrBefore(frameTime);
        // A tracked surface (onStep) must see every step: it cannot follow a jump to a kept state.
        if (state && state->time > now() && !onStep) resumeFrom(*state);
        while (now() < frameTime && secondPassSteps() < o.maxSteps) {
            const double dt = std::min(frameTime - now(), evolution->stableTimeStep());
            // The line ends on the target's volume at T; from there the shape converges onto the
            // target itself, which has that volume, so the control stops.
            auto& volume = evolution->terms().volume;
            if (volume && now() + dt < duration) {
                volume->targetVolume = v0 + (v1 - v0) * (now() + dt) / duration;
            } else {
                volume.reset();
            }
            evolution->step(dt);
            stepped(field);
            report(progress, 0.5 + 0.45 * now() / std::max(duration, 1e-30));
        }
        if (frame + 1 == o.frames) {
            // The last approach matches the band's values: thin parts, which only the values
            // near the surface hold, then end on the target's too.
            evolution->terms().target->matchValues = true;
            settle(*evolution, field, goal, o.maxSteps - secondPassSteps(), summary.stop, part(progress, 0.95, 1.0),
                   onStep);
        }
        emit(frame);
    }
    summary.steps = first.steps + secondPassSteps();
    summary.duration = now();
    const ShapeDistance final = finalDistance(field, goal);
    // Float phi read on the target's own surface leaves denormal noise (2.8e-45 was printed).
    const auto floatNoise = [&](double d) { return d < 1e-6 * target.voxelSize() ? 0.0 : d; };
    summary.finalDistanceWorld = floatNoise(final.maxResolvedWorld);
    summary.worstDistanceWorld = floatNoise(final.maxWorld);
    summary.resolvedFraction = final.resolvedFraction;
    summary.converged = morphConverged(final, tolerance, target.voxelSize());
    if (summary.converged) summary.stop = MorphStop::Converged;
    return summary;
}

}  // namespace sculpt
