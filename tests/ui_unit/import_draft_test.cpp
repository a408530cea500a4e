// SPDX-License-Identifier: Apache-2.0
// The Import panel's draft without a window: the preview is rebuilt when an option that shapes
// it changes and only then, follows the iso-value, and an option the import refuses leaves no
// preview and says why, until it is set right again.

#include "core/mesh/field_measures.h"
#include "ui/document/import_draft.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

using namespace sculpt;
using namespace sculpt::ui;

TEST(ImportDraft, ThePreviewIsRebuiltOnlyWhenAnOptionThatShapesItChanges)
{
    const char* mri = "/usr/share/mricron/templates/ch2bet.nii.gz";
    if (!std::filesystem::exists(mri)) GTEST_SKIP() << mri << " missing: apt-get install mricron-data";
    auto file = std::make_shared<ImportPreview>(mri);
    const ImportOptions defaults;
    ImportDraft draft(file, file->surface(defaults), 1.0, defaults);
    EXPECT_EQ(draft.iso(), file->otsuThreshold(defaults));  // Otsu's when no iso-value is set
    EXPECT_FALSE(draft.refresh());
    const double otsuVolume = measureField(*draft.preview()).volume;

    draft.options.voxelSize = 0.5;  // the import's voxels, not the preview's
    EXPECT_FALSE(draft.stale());
    EXPECT_FALSE(draft.refresh());

    const auto [low, high] = file->range(defaults);
    draft.options.iso = draft.iso() + 0.5 * (high - draft.iso());
    EXPECT_TRUE(draft.stale());
    EXPECT_TRUE(draft.refresh());
    ASSERT_NE(draft.preview(), nullptr);
    EXPECT_LT(measureField(*draft.preview()).volume, 0.9 * otsuVolume);
    EXPECT_FALSE(draft.refresh());

    draft.options.iso = high + (high - low);  // above every sample: nothing inside
    EXPECT_TRUE(draft.refresh());
    EXPECT_EQ(draft.preview(), nullptr);
    EXPECT_FALSE(draft.problem().empty());

    draft.options.iso.reset();
    EXPECT_TRUE(draft.refresh());
    ASSERT_NE(draft.preview(), nullptr);
    EXPECT_TRUE(draft.problem().empty());
    EXPECT_DOUBLE_EQ(measureField(*draft.preview()).volume, otsuVolume);
}
