// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/sculpt_session.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/brushes/brush.h"
#include "core/field/leaf_journal.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

// Below this, stamps pile up for no visible difference (and a long stroke takes hours).
constexpr double kMinSpacing = 0.01;
// Samples farther than this many model sizes beyond the model's box reach nothing, only cost
// stamps on the way (a sample at 10^6 is a million of them).
constexpr double kSampleReachModels = 4.0;

void validateSettings(const Stroke& stroke)
{
    stroke.brush.validate();
    if (!(stroke.spacing >= kMinSpacing && stroke.spacing <= 4.0)) {
        throw InputError("field 'spacing' must be in [" + formatNumber(kMinSpacing) + ", 4] radii (got " +
                         formatNumber(stroke.spacing) + ")");
    }
}

/// A stroke's stamps, mirrors included, bounded before any is made: the path over the step,
/// once more for the first stamp, times the mirror images.
double stampsNeeded(const Stroke& stroke)
{
    double length = 0.0;
    for (size_t i = 1; i < stroke.samples.size(); ++i)
        length += (stroke.samples[i].positionWorld - stroke.samples[i - 1].positionWorld).length();
    const double mirrors =
        (stroke.symmetry.x ? 2.0 : 1.0) * (stroke.symmetry.y ? 2.0 : 1.0) * (stroke.symmetry.z ? 2.0 : 1.0);
    return (length / (stroke.spacing * stroke.brush.radiusWorld) + 2.0) * mirrors;
}

void validateSample(const StrokeSample& s, size_t index)
{
    const std::string where = "field 'samples[" + std::to_string(index) + "].";
    if (!s.positionWorld.isFinite()) throw InputError(where + "position' is not finite");
    if (!s.viewDirection.isFinite()) throw InputError(where + "view' is not finite");
    if (!(s.pressure > 0.0 && s.pressure <= 1.0)) {
        throw InputError(where + "pressure' must be in (0, 1] (got " + formatNumber(s.pressure) + ")");
    }
}

}  // namespace

void requireSampleCount(std::size_t samples)
{
    if (samples > kMaxStrokeSamples) {
        throw InputError("field 'samples' holds " + std::to_string(samples) + " samples, more than a stroke may (" +
                         std::to_string(kMaxStrokeSamples) + "): split it into several strokes");
    }
}

void validateStroke(const Stroke& stroke)
{
    validateSettings(stroke);
    if (stroke.samples.empty()) throw InputError("field 'samples' is empty: a stroke needs at least one");
    requireSampleCount(stroke.samples.size());
    for (size_t i = 0; i < stroke.samples.size(); ++i) validateSample(stroke.samples[i], i);
    const double stamps = stampsNeeded(stroke);
    if (!(stamps <= double(kMaxStrokeStamps))) {
        throw InputError("the stroke would make " + formatNumber(stamps) + " stamps, more than " +
                         std::to_string(kMaxStrokeStamps) + ": split it, or use a larger spacing or radius");
    }
}

struct SculptSession::LiveStroke {
    LiveStroke(const Stroke& settings, const openvdb::BBoxd& box) : stroke(settings), stepper(settings), reach(box)
    {
        stroke.samples.clear();
    }
    Stroke stroke;
    StrokeStepper stepper;
    LeafJournal journal;
    StrokeReport report;
    /// The model's world box at the stroke's start, grown by each stamp's reach: a superset of
    /// the band's leaves kept per stamp, so no sample walks the whole tree.
    openvdb::BBoxd reach;
    std::vector<KeepOut> keepOuts;  // pieces its stamps stop at
};

SculptSession::SculptSession(FieldImage field, bool liveMesh, std::size_t undoBudgetBytes, const Progress& meshing)
    : mField(std::move(field)), mHistory(undoBudgetBytes)
{
    mField.takeDirtyRegion();
    if (liveMesh) {
        mMesher.emplace();
        mMesher->rebuild(mField, meshing);
    }
}

SculptSession::~SculptSession() = default;
SculptSession::SculptSession(SculptSession&&) noexcept = default;
SculptSession& SculptSession::operator=(SculptSession&&) noexcept = default;

openvdb::CoordBBox SculptSession::leafBox() const
{
    openvdb::CoordBBox box;  // of the leaves: a voxel-exact box would visit every voxel
    mField.grid().tree().evalLeafBoundingBox(box);
    return box;
}

double SculptSession::sizeOf(const openvdb::CoordBBox& box) const
{
    return box.empty() ? 0.0 : double(box.dim().asVec3d().length()) * mField.voxelSize();
}

double SculptSession::modelSize() const { return sizeOf(leafBox()); }

void SculptSession::checkNearModel(const StrokeSample& sample, std::size_t index) const
{
    const openvdb::BBoxd& world = mLive->reach;
    if (world.empty()) return;
    const openvdb::Vec3d p = sample.positionWorld;
    const openvdb::Vec3d nearest(std::clamp(p.x(), world.min().x(), world.max().x()),
                                 std::clamp(p.y(), world.min().y(), world.max().y()),
                                 std::clamp(p.z(), world.min().z(), world.max().z()));
    const double size = world.extents().length(), away = (p - nearest).length();
    if (away > kSampleReachModels * size) {
        throw InputError("field 'samples[" + std::to_string(index) + "].position' lies " + formatNumber(away) +
                         " from the model (" + formatNumber(size) + " " + mField.units() +
                         " across): a stroke stays within " + formatNumber(kSampleReachModels) + " model sizes of it");
    }
}

void SculptSession::checkRadius(const BrushSettings& brush, double size) const
{
    if (brush.radiusWorld > size) {
        throw InputError("field 'radius' (" + formatNumber(brush.radiusWorld) + ") is larger than the model (" +
                         formatNumber(size) + " " + mField.units() + " across)");
    }
}

SculptSession::StrokeReport SculptSession::applyStroke(const Stroke& stroke)
{
    validateStroke(stroke);
    beginStroke(stroke);
    try {
        for (const StrokeSample& sample : stroke.samples) extendStroke(sample);
        return endStroke().report;
    } catch (...) {
        cancelStroke();  // a stroke lands whole or not at all
        throw;
    }
}

void SculptSession::beginStroke(const Stroke& settings, std::vector<KeepOut> keepOutOf)
{
    if (mLive) throw std::logic_error("beginStroke: a stroke is already active");
    validateSettings(settings);
    const openvdb::CoordBBox box = leafBox();  // the one pass over the tree's nodes a stroke makes
    checkRadius(settings.brush, sizeOf(box));
    mLive = std::make_unique<LiveStroke>(settings,
                                         box.empty() ? openvdb::BBoxd() : mField.grid().transform().indexToWorld(box));
    mLive->keepOuts = std::move(keepOutOf);
}

void SculptSession::stamp(const std::vector<BrushStamp>& stamps, StrokeReport& report)
{
    for (const BrushStamp& s : stamps) {
        const DirtyRegion stamped = applyStamp(mField, mLive->stroke.brush, s, &mLive->journal);
        for (const KeepOut& other : mLive->keepOuts) keepOut(mField, stamped, other);
        const openvdb::Vec3d reach(mLive->stroke.brush.radiusWorld + mField.halfWidthVoxels() * mField.voxelSize());
        for (const openvdb::Vec3d& c : {s.centreWorld, s.previousWorld})
            mLive->reach.expand(openvdb::BBoxd(c - reach, c + reach));
        ++report.stamps;
    }
}

SculptSession::StrokeReport SculptSession::extendStroke(const StrokeSample& sample)
{
    if (!mLive) throw std::logic_error("extendStroke: no active stroke");
    validateSample(sample, mLive->stroke.samples.size());
    checkNearModel(sample, mLive->stroke.samples.size());
    mLive->stroke.samples.push_back(sample);
    StrokeReport report;
    stamp(mLive->stepper.add(sample), report);
    mLive->report.stamps += report.stamps;
    return report;
}

SculptSession::FinishedStroke SculptSession::endStroke()
{
    if (!mLive) throw std::logic_error("endStroke: no active stroke");
    stamp(mLive->stepper.finish(), mLive->report);
    updateMesh();
    std::unique_ptr<LiveStroke> live = std::move(mLive);
    live->report.leavesChanged = live->journal.leafCount();
    live->report.journalBytes = live->journal.memoryBytes();
    mHistory.push(std::move(live->journal));
    return {std::move(live->stroke), live->report};
}

const LeafJournal* SculptSession::strokeJournal() const { return mLive ? &mLive->journal : nullptr; }

void SculptSession::cancelStroke()
{
    if (!mLive) return;
    mLive->journal.swap(mField);
    mLive.reset();
    updateMesh();
}

void SculptSession::replaceField(FieldImage result)
{
    if (mLive) throw std::logic_error("replaceField during a live stroke");
    LeafJournal journal = LeafJournal::wholeGrid(result.mutableGridPtr());
    journal.swap(mField);  // the field holds the result now, the journal what it replaced
    mHistory.push(std::move(journal));
    updateMesh();
}

bool SculptSession::editMask(MaskOperation operation, int times)
{
    if (mLive) throw std::logic_error("editMask during a live stroke");
    LeafJournal journal;
    applyMaskOperation(mField, operation, times, &journal);
    const bool changed = !journal.empty();
    mHistory.push(std::move(journal));
    updateMesh();
    return changed;
}

bool SculptSession::selectMask(const MaskSelection& selection)
{
    if (mLive) throw std::logic_error("selectMask during a live stroke");
    LeafJournal journal;
    applyMaskSelection(mField, selection, &journal);
    const bool changed = !journal.empty();
    mHistory.push(std::move(journal));
    updateMesh();
    return changed;
}

void SculptSession::replaceMask(openvdb::FloatGrid::Ptr mask)
{
    if (mLive) throw std::logic_error("replaceMask during a live stroke");
    if (mask && mask->transform() != mField.grid().transform())
        throw InputError("the mask '" + mask->getName() + "' is not on the surface's voxels (another transform)");
    LeafJournal journal;
    journal.saveWholeMask(std::move(mask));
    journal.swap(mField);  // the field holds the new mask now, the journal the one it replaced
    mHistory.push(std::move(journal));
    updateMesh();
}

void SculptSession::drillHoles(const std::vector<DrainHole>& holes)
{
    if (mLive) throw std::logic_error("drillHoles during a live stroke");
    LeafJournal journal;
    cutDrainHoles(mField, holes, &journal);
    mHistory.push(std::move(journal));
    updateMesh();
}

bool SculptSession::undo()
{
    const bool done = mHistory.undo(mField);
    updateMesh();
    return done;
}

bool SculptSession::redo()
{
    const bool done = mHistory.redo(mField);
    updateMesh();
    return done;
}

void SculptSession::updateMesh()
{
    const DirtyRegion dirty = mField.takeDirtyRegion();
    if (mMesher) mRemeshed += mMesher->update(mField, dirty);
}

}  // namespace sculpt
