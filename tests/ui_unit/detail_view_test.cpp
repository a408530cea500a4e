// SPDX-License-Identifier: Apache-2.0
// The level-of-detail rule on chunks laid out by hand: which go coarse under a triangle budget.

#include "ui/view/detail_view.h"

#include <gtest/gtest.h>

using namespace sculpt::ui;

namespace {

/// Ten unit chunks in a row along +z, 10 to 100 away from an eye at the origin, each of 1000
/// triangles (100 coarse).
std::vector<ChunkDetail> row()
{
    std::vector<ChunkDetail> chunks;
    for (int i = 1; i <= 10; ++i) {
        const double z = 10.0 * i;
        chunks.push_back({glm::dvec3(-0.5, -0.5, z), glm::dvec3(0.5, 0.5, z + 1.0), 1000, 100, false});
    }
    return chunks;
}

DetailView moving(std::size_t budget)
{
    DetailView view;
    view.still = false;
    // A perspective pixel grows with distance: a voxel of 1 covers 100 pixels 10 away, 10 at 100.
    view.pixelSizeAt = [](const glm::dvec3& p) { return glm::length(p) / 1000.0; };
    view.triangleBudget = budget;
    return view;
}

std::size_t drawn(const std::vector<ChunkDetail>& chunks, const std::vector<bool>& coarse)
{
    std::size_t sum = 0;
    for (std::size_t i = 0; i < chunks.size(); ++i)
        sum += coarse[i] ? chunks[i].coarseTriangles : chunks[i].fullTriangles;
    return sum;
}

}  // namespace

TEST(DetailView, OverBudgetTheChunksSmallestOnScreenGoCoarseFirstUntilTheTrianglesFit)
{
    const std::vector<ChunkDetail> chunks = row();
    const std::vector<bool> coarse = chooseCoarse(chunks, 1.0, moving(5500));
    EXPECT_LE(drawn(chunks, coarse), 5500u);
    for (std::size_t i = 0; i < chunks.size(); ++i) EXPECT_EQ(coarse[i], i >= 5) << "chunk " << i;
}

TEST(DetailView, UnderBudgetOnlyVoxelsUnderTwoPixelsGoCoarse)
{
    const std::vector<ChunkDetail> chunks = row();
    // Voxels of 0.03: 3 pixels at 10 away, 0.3 at 100: the chunks from 20 on go coarse.
    const std::vector<bool> coarse = chooseCoarse(chunks, 0.03, moving(1000000));
    for (std::size_t i = 0; i < chunks.size(); ++i) EXPECT_EQ(coarse[i], i >= 1) << "chunk " << i;
    EXPECT_EQ(chooseCoarse(chunks, 1.0, moving(1000000)), std::vector<bool>(chunks.size(), false));
}

TEST(DetailView, TheBrushesChunkAChangedOneAndAStillViewStayFullWhateverTheBudget)
{
    std::vector<ChunkDetail> chunks = row();
    chunks[9].pinned = true;  // changed this frame
    DetailView view = moving(1);
    view.brushCentre = glm::dvec3(0.0, 0.0, 80.5);  // inside chunk 7
    view.brushRadius = 0.1;
    const std::vector<bool> coarse = chooseCoarse(chunks, 1.0, view);
    for (std::size_t i = 0; i < chunks.size(); ++i) EXPECT_EQ(coarse[i], i != 7 && i != 9) << "chunk " << i;
    view.still = true;
    EXPECT_EQ(chooseCoarse(chunks, 1.0, view), std::vector<bool>(chunks.size(), false));
}
