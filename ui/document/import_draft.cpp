// SPDX-License-Identifier: Apache-2.0
#include "ui/document/import_draft.h"

#include "core/base/errors.h"

#include <chrono>

namespace sculpt::ui {

namespace {

bool sameOptions(const ImportOptions& a, const ImportOptions& b)
{
    return a.iso == b.iso && a.label == b.label && a.crop == b.crop && a.smoothSigma == b.smoothSigma &&
           a.largestComponent == b.largestComponent;  // the voxel size and the anti-aliasing do not change the preview
}

}  // namespace

ImportDraft::ImportDraft(std::shared_ptr<ImportPreview> file, FieldImage first, double firstMs, ImportOptions defaults)
    : options(defaults), mFile(std::move(file)), mPreview(std::move(first)), mPreviewed(defaults), mPreviewMs(firstMs)
{
    labelPieces = mFile->isScan() && mFile->labelMap();  // a segmentation: its structures apart
}

double ImportDraft::iso()
{
    return scanIso(options, [&] { return mFile->isScan() ? mFile->otsuThreshold(options) : 0.0; });
}

bool ImportDraft::stale() const { return !sameOptions(options, mPreviewed); }

bool ImportDraft::refresh()
{
    if (!stale()) return false;
    const auto start = std::chrono::steady_clock::now();
    mPreviewed = options;
    try {
        mPreview = mFile->surface(options);
        mProblem.clear();
    } catch (const InputError& e) {
        mPreview.reset();
        mProblem = e.what();
    }
    mPreviewMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return true;
}

const char* importResultName(ImportDraft::Result result)
{
    switch (result) {
    case ImportDraft::Result::NewDocument: return "new document";
    case ImportDraft::Result::Union: return "union";
    case ImportDraft::Result::Difference: return "difference";
    }
    return "";
}

}  // namespace sculpt::ui
