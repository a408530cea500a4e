// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file status_tally.h
/// @brief The status bar's figures, kept current once a frame at the cost of what changed: the
///        sculpted piece's volume and area re-tallied per block the mesher changed, the passes
///        over the whole tree (active voxels, memory) only after a change and not during a
///        stroke, the topology (Euler characteristic, shells) only when asked.

#include "core/mesh/surface_statistics.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <string>

namespace sculpt {
class Document;
}  // namespace sculpt

namespace sculpt::ui {

class ModelDisplay;

/// The figures of the status bar.
struct StatusFigures {
    double frameMs = 0.0;
    /// The piece sculpted (of several), and the triangles of every piece shown.
    std::string piece;
    std::size_t pieces = 1, allTriangles = 0;
    std::size_t triangles = 0, activeVoxels = 0, blocks = 0, memoryBytes = 0, undoBytes = 0;
    /// Where the memory goes: the field's tree, the mesher's block meshes, the display's VTK
    /// geometry (the rest of memoryBytes: the GL driver's copy of it, libraries, the window).
    std::size_t gridBytes = 0, mesherBytes = 0, displayBytes = 0;
    double volume = 0.0, area = 0.0;
    long long euler = 0;
    std::size_t shells = 0;
    /// Since the last report: blocks uploaded and dropped by the display, bytes handed to VTK.
    std::size_t blocksUploaded = 0, blocksRemoved = 0, bytesUploaded = 0, chunksUploaded = 0;
};

class StatusTally {
public:
    /// The measures start again: another document, or another piece sculpted.
    void reset();
    /// Brings the figures up to date with `document` drawn by `display` (and `otherTriangles`
    /// of the other pieces shown). `duringStroke`: no whole-tree pass now; `topology`: the Euler
    /// characteristic and shells too; `sampleMemory`: the process's resident memory again.
    void refresh(const Document& document, const ModelDisplay& display, std::size_t otherTriangles, bool duringStroke,
                 bool topology, bool sampleMemory);
    /// Counts the display's uploads of this frame (until the next report).
    void countUploads(const ModelDisplay& display);
    void setFrameMs(double ms) { mFigures.frameMs = ms; }

    const StatusFigures& figures() const { return mFigures; }
    /// The sculpted piece's triangles (what the display's level of detail weighs).
    std::size_t triangles() const { return mStatistics.triangles(); }
    /// The sculpted piece's size (SculptSession::modelSize), as of its last whole-tree pass.
    double modelSize() const { return mModelSize; }

    /// Its figures in the window's report (volume, area, triangles, topology, uploads, memory);
    /// the upload counts start again.
    void report(nlohmann::json& out);

private:
    SurfaceStatistics mStatistics;
    StatusFigures mFigures;
    std::uint64_t mTopologyVersion = ~std::uint64_t(0);
    std::uint64_t mMeasuredVersion = ~std::uint64_t(0);  // of the active voxels, memory and model size
    double mModelSize = 0.0;
    SurfaceTopology mTopology;
};

}  // namespace sculpt::ui
