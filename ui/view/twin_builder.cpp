// SPDX-License-Identifier: Apache-2.0
#include "ui/view/twin_builder.h"

#include "ui/view/block_cluster.h"
#include "ui/view/block_polydata.h"

#include <vtkPolyData.h>

#include <memory>
#include <utility>

namespace sculpt::ui {

TwinBuilder::~TwinBuilder() { mTasks.wait(); }

void TwinBuilder::request(const openvdb::Coord& origin, std::uint64_t generation, vtkSmartPointer<vtkPolyData> full,
                          double cellWorld)
{
    // Shared, not captured by value: TBB calls its tasks as const, and the source must move on.
    auto twin = std::make_shared<Twin>(Twin{origin, generation, {}, std::move(full)});
    mTasks.run([this, twin, cellWorld] {
        twin->mesh = clusterBlockMesh(blockMeshOf(twin->source), cellWorld);
        const std::lock_guard<std::mutex> lock(mMutex);
        mDone.push_back(std::move(*twin));  // the source's reference with it: released on the UI thread
    });
}

std::vector<TwinBuilder::Twin> TwinBuilder::collect()
{
    std::vector<Twin> done;
    const std::lock_guard<std::mutex> lock(mMutex);
    done.swap(mDone);
    return done;
}

void TwinBuilder::wait() { mTasks.wait(); }

}  // namespace sculpt::ui
