// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file import_draft.h
/// @brief The Import panel's work: the file read once (ImportPreview), the options the panel
///        edits, what the result becomes, and the coarse preview those options give, rebuilt
///        whenever they change. Nothing here touches the document: Apply imports afresh.

#include "sculpt/session/import_preview.h"

#include <memory>
#include <optional>
#include <string>

namespace sculpt::ui {

class ImportDraft {
public:
    enum class Result { NewDocument, Union, Difference };

    /// `file` read, `first` its preview for the default options, made in `firstMs` (both by the
    /// reading job).
    ImportDraft(std::shared_ptr<ImportPreview> file, FieldImage first, double firstMs, ImportOptions defaults);

    ImportPreview& file() { return *mFile; }
    const ImportPreview& file() const { return *mFile; }
    ImportOptions options;  ///< as the panel sets them
    Result result = Result::NewDocument;
    /// A label map imported as a new document of one piece per label (importLabelPieces): the
    /// default for a label map of two labels or more besides the background.
    bool labelPieces = false;

    /// The iso-value the options give: theirs, else Otsu's (scans).
    double iso();
    /// Rebuilds the preview if the options changed since it was made; true if it did. On an
    /// error the preview is gone and problem() says why.
    bool refresh();
    const FieldImage* preview() const { return mPreview ? &*mPreview : nullptr; }
    const std::string& problem() const { return mProblem; }
    /// How long the last preview took to make, milliseconds.
    double previewMs() const { return mPreviewMs; }
    /// True while the options differ from those of the preview shown.
    bool stale() const;

private:
    std::shared_ptr<ImportPreview> mFile;
    std::optional<FieldImage> mPreview;
    ImportOptions mPreviewed;  // the options of the preview (or problem) shown
    std::string mProblem;
    double mPreviewMs = 0.0;
};

/// "new document", "union", "difference".
const char* importResultName(ImportDraft::Result result);

}  // namespace sculpt::ui
