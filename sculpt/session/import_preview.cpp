// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/import_preview.h"

#include "core/scan/largest_component.h"
#include "core/scan/scan_readers.h"
#include "core/scan/scan_to_level_set.h"

#include <algorithm>

namespace sculpt {

ImportPreview::ImportPreview(const std::filesystem::path& path) : mPath(path)
{
    if (isMeshPath(path)) {
        mMesh = readMesh(path);
        mMeshReport = inspectMesh(*mMesh);
        mDefaultVoxelSize = voxelSizeFor(*mMesh);
        mPreviewVoxelSize = voxelSizeFor(*mMesh, kPreviewVoxelsAcross);
        return;
    }
    mScan = readScan(path);
    mTwoValued = mScan->twoValued();
    mLabels = mScan->labels();
    mLabelMap = mLabels.size() > 2 && mScan->sameNeighbourFraction() >= kLeastLabelMapAgreement;
    mDefaultVoxelSize = nativeVoxelSize(*mScan);
    mPreviewVoxelSize = std::max(mDefaultVoxelSize, mScan->worldExtent() / kPreviewVoxelsAcross);
}

void ImportPreview::prepare(const ImportOptions& options)
{
    if (mPrepared.kept && mPrepared.crop == options.crop && mPrepared.label == options.label &&
        mPrepared.smoothSigma == options.smoothSigma)
        return;
    Prepared next;
    next.crop = options.crop;
    next.label = options.label;
    next.smoothSigma = options.smoothSigma;
    next.kept = options.crop ? mScan->cropped(*options.crop) : *mScan;
    if (options.label) next.kept = next.kept->labelMask(*options.label);
    if (options.smoothSigma > 0.0) next.kept = next.kept->smoothed(options.smoothSigma);
    next.histogram = next.kept->histogram(kHistogramBins);
    next.otsu = next.kept->otsuThreshold();
    next.filtered = next.kept->antiAliased(mPreviewVoxelSize);
    if (!next.filtered) next.filtered = next.kept;
    mPrepared = std::move(next);
}

const std::vector<double>& ImportPreview::histogram(const ImportOptions& options)
{
    prepare(options);
    return mPrepared.histogram;
}

double ImportPreview::otsuThreshold(const ImportOptions& options)
{
    prepare(options);
    return mPrepared.otsu;
}

std::pair<double, double> ImportPreview::range(const ImportOptions& options)
{
    prepare(options);
    return mPrepared.kept->range();
}

FieldImage ImportPreview::surface(const ImportOptions& options)
{
    FieldImage field = [&] {
        if (mMesh) return meshToField(*mMesh, mPreviewVoxelSize);
        prepare(options);
        return scanToLevelSet(*mPrepared.filtered, scanIso(options, [&] { return mPrepared.otsu; }), mPreviewVoxelSize);
    }();
    if (options.largestComponent) keepLargestComponent(field);
    return field;
}

}  // namespace sculpt
