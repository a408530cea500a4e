// SPDX-License-Identifier: Apache-2.0
#include "ui/document/open_preview.h"

#include "core/mesh/preview_mesh.h"

namespace sculpt::ui {

void OpenPreview::offer(const FieldImage& field)
{
    const int stride = previewStride(field, mBudget);
    if (stride == 1) return;
    Surface surface{previewMesh(field, stride), field.grid().transform().copy()};
    const std::lock_guard<std::mutex> lock(mMutex);
    mSurface = std::move(surface);
}

std::optional<OpenPreview::Surface> OpenPreview::take()
{
    const std::lock_guard<std::mutex> lock(mMutex);
    return std::exchange(mSurface, std::nullopt);
}

}  // namespace sculpt::ui
