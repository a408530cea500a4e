#include "sculpt/session/sculpt_session.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/brushes/brush.h"
#include "core/field/leaf_journal.h"

#include <cmath>

namespace sculpt {

void validateStroke(const Stroke& stroke)
{
    stroke.brush.validate();
    if (!(stroke.spacing > 0.0 && stroke.spacing <= 4.0)) {
        throw InputError("field 'spacing' must be in (0, 4] radii (got " + formatNumber(stroke.spacing) + ")");
    }
    if (stroke.samples.empty()) throw InputError("field 'samples' is empty: a stroke needs at least one");
    for (size_t i = 0; i < stroke.samples.size(); ++i) {
        const StrokeSample& s = stroke.samples[i];
        const std::string where = "field 'samples[" + std::to_string(i) + "].";
        if (!s.positionWorld.isFinite()) throw InputError(where + "position' is not finite");
        if (!s.viewDirection.isFinite()) throw InputError(where + "view' is not finite");
        if (!(s.pressure > 0.0 && s.pressure <= 1.0)) {
            throw InputError(where + "pressure' must be in (0, 1] (got " + formatNumber(s.pressure) + ")");
        }
    }
}

SculptSession::SculptSession(FieldImage field, bool liveMesh, std::size_t undoBudgetBytes)
    : mField(std::move(field)), mHistory(undoBudgetBytes)
{
    mField.takeDirtyRegion();
    if (liveMesh) {
        mMesher.emplace();
        mMesher->rebuild(mField);
    }
}

double SculptSession::modelSize() const
{
    openvdb::CoordBBox box;  // of the leaves: a voxel-exact box would visit every voxel per stroke
    if (!mField.grid().tree().evalLeafBoundingBox(box)) return 0.0;
    return double(box.dim().asVec3d().length()) * mField.voxelSize();
}

SculptSession::StrokeReport SculptSession::applyStroke(const Stroke& stroke)
{
    validateStroke(stroke);
    const double size = modelSize();
    if (stroke.brush.radiusWorld > size) {
        throw InputError("field 'radius' (" + formatNumber(stroke.brush.radiusWorld) + ") is larger than the model (" +
                         formatNumber(size) + " " + mField.units() + " across)");
    }
    LeafJournal journal;
    StrokeReport report;
    try {
        for (const BrushStamp& stamp : strokeStamps(stroke)) {
            applyStamp(mField, stroke.brush, stamp, &journal);
            updateMesh();
            ++report.stamps;
        }
    } catch (...) {
        journal.swap(mField);  // a stroke lands whole or not at all
        updateMesh();
        throw;
    }
    report.leavesChanged = journal.leafCount();
    report.journalBytes = journal.memoryBytes();
    mHistory.push(std::move(journal));
    return report;
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
    if (mMesher) mMesher->update(mField, dirty);
}

}  // namespace sculpt
