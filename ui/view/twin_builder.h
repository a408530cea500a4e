// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file twin_builder.h
/// @brief The coarse twins of display chunks, clustered on a worker thread so that neither a
///        frame nor a stroke waits for them.
///
/// A request hands over the chunk's VTK geometry (read only: the display never changes a
/// polydata it made, it makes a new one) and the chunk's generation; a finished twin comes back
/// with the geometry's reference, so that VTK objects are only ever released on the UI thread.
/// The display drops a twin whose generation is no longer its chunk's.

#include "core/mesh/block_mesh.h"

#include <openvdb/Types.h>
#include <tbb/task_group.h>
#include <vtkSmartPointer.h>

#include <mutex>
#include <vector>

class vtkPolyData;

namespace sculpt::ui {

class TwinBuilder {
public:
    struct Twin {
        openvdb::Coord origin;
        std::uint64_t generation = 0;
        BlockMesh mesh;
        vtkSmartPointer<vtkPolyData> source;  // released here, on the UI thread
    };

    ~TwinBuilder();

    /// Clusters `full` into cells of `cellWorld` on a worker thread.
    void request(const openvdb::Coord& origin, std::uint64_t generation, vtkSmartPointer<vtkPolyData> full,
                 double cellWorld);
    /// The twins finished since the last call.
    std::vector<Twin> collect();
    /// Waits until every request has finished (then collect() has them all).
    void wait();

private:
    tbb::task_group mTasks;
    std::mutex mMutex;
    std::vector<Twin> mDone;  // guarded by mMutex
};

}  // namespace sculpt::ui
