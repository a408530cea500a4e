// SPDX-License-Identifier: Apache-2.0
#include "ui/status/status_tally.h"

#include "sculpt/session/document.h"
#include "ui/status/process_memory.h"
#include "ui/view/model_display.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

void StatusTally::reset()
{
    mStatistics = SurfaceStatistics();
    mTopologyVersion = mMeasuredVersion = ~std::uint64_t(0);
}

void StatusTally::refresh(const Document& document, const ModelDisplay& display, std::size_t otherTriangles,
                          bool duringStroke, bool topology, bool sampleMemory)
{
    const SculptSession& session = document.session();
    mStatistics.update(*session.mesher());
    mFigures.triangles = mStatistics.triangles();
    mFigures.pieces = document.pieces().size();
    mFigures.piece = document.pieces()[document.activePiece()].look.name;
    mFigures.allTriangles = mFigures.triangles + otherTriangles;
    mFigures.volume = mStatistics.volume();
    mFigures.area = mStatistics.area();
    // Whole-tree passes: only after a change, and not per frame of a stroke (at its end).
    if (mMeasuredVersion != session.mesher()->version() && !duringStroke) {
        mFigures.activeVoxels = std::size_t(session.field().grid().activeVoxelCount());
        mFigures.gridBytes = std::size_t(session.field().grid().memUsage());
        mFigures.mesherBytes = session.mesher()->memoryBytes();
        mModelSize = session.modelSize();
        mMeasuredVersion = session.mesher()->version();
    }
    mFigures.blocks = display.blockCount();
    mFigures.undoBytes = 0;  // every piece's: the history spans them
    for (const DocumentPiece& piece : document.pieces()) mFigures.undoBytes += piece.session->history().memoryBytes();
    if (sampleMemory) mFigures.memoryBytes = residentBytes();
    mFigures.displayBytes = display.heldBytes();
    if (topology && mTopologyVersion != session.mesher()->version()) {
        mTopology = mStatistics.topology(*session.mesher());
        mTopologyVersion = session.mesher()->version();
    }
    mFigures.euler = mTopology.euler;
    mFigures.shells = mTopology.shells;
}

void StatusTally::countUploads(const ModelDisplay& display)
{
    mFigures.blocksUploaded += display.lastUploads();
    mFigures.blocksRemoved += display.lastRemovals();
    mFigures.bytesUploaded += display.lastUploadBytes();
    mFigures.chunksUploaded += display.lastChunkUploads();
}

void StatusTally::report(nlohmann::json& out)
{
    out["volume"] = mFigures.volume;
    out["area"] = mFigures.area;
    out["triangles"] = mFigures.triangles;
    out["euler"] = mFigures.euler;
    out["shells"] = mFigures.shells;
    out["uploaded"] = mFigures.blocksUploaded;  // since the previous report
    out["removed"] = mFigures.blocksRemoved;
    out["bytes_uploaded"] = mFigures.bytesUploaded;
    out["chunks_uploaded"] = mFigures.chunksUploaded;
    out["frame_ms"] = mFigures.frameMs;
    out["memory"] = {{"resident", residentBytes()},
                     {"grid", mFigures.gridBytes},
                     {"mesher", mFigures.mesherBytes},
                     {"display", mFigures.displayBytes},
                     {"undo", mFigures.undoBytes}};
    mFigures.blocksUploaded = mFigures.blocksRemoved = mFigures.bytesUploaded = mFigures.chunksUploaded = 0;
}

}  // namespace sculpt::ui
