#include "ui/modes/import_mode.h"

#include "core/base/text_format.h"
#include "core/field/csg_combine.h"
#include "sculpt/session/document.h"
#include "sculpt/session/shape_import.h"
#include "ui/modes/mode_host.h"
#include "ui/panels/panels.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace sculpt::ui {

namespace {

constexpr double kIsoStep = 0.01;  // of the samples' range, per PageUp/PageDown

/// "iso-value 120, voxel size 0.5; WARNING", what an import's notice adds.
std::string importSummary(const ImportReport& report)
{
    std::string text = "iso-value " + formatNumber(report.iso) + ", voxel size " + formatNumber(report.voxelSize);
    if (report.maskAntiAliased)
        text += report.twoValued ? ", a mask: terraces anti-aliased" : ", terraces anti-aliased";
    if (!report.warnings.empty()) text += "; " + report.warnings.front();
    return text;
}

}  // namespace

ImportMode::ImportMode(vtkRenderer* scene, ImportDraft draft)
    : mDraft(std::move(draft)), mPreview(scene, ShapeStyle::preview())
{
    mPreview.set(mDraft.preview());
}

std::string ImportMode::waitNotice() const { return "an import is open: apply it (Enter) or cancel it (Esc) first"; }

std::string ImportMode::hint() const
{
    return "import " + mDraft.file().path().filename().string() + ": Enter applies, Esc cancels";
}

bool ImportMode::sync(double /*now*/)
{
    if (!mDraft.refresh()) return false;
    mPreview.set(mDraft.preview());
    return true;
}

void ImportMode::step(int direction)
{
    if (!mDraft.file().isScan() || mDraft.options.label) return;  // a label's surface has no iso-value to step
    const auto [lo, hi] = mDraft.file().range(mDraft.options);
    mDraft.options.iso = std::clamp(mDraft.iso() + direction * kIsoStep * (hi - lo), lo, hi);
}

bool ImportMode::accept(ModeHost& host)
{
    const ImportDraft::Result result = mDraft.result;
    const bool replaces = result == ImportDraft::Result::NewDocument;
    if (replaces && !host.guardUnsaved(Command::Confirm)) return false;
    host.autosaveNow();
    ImportOptions options = mDraft.options;
    if (!replaces) options.voxelSize = host.document().session().field().voxelSize();  // the document's lattice
    const std::filesystem::path path = mDraft.file().path();
    auto report = std::make_shared<ImportReport>();
    if (replaces && mDraft.labelPieces) {  // a piece per label, each meshed on the job's thread
        host.startDocument(
            "import " + path.filename().string() + " as pieces",
            [path, options, report](const Progress& p, const ModeHost::FieldReady& ready) {
                std::vector<Piece> pieces = importLabelPieces(path, options, *report, scaledProgress(p, 0.0, 0.7));
                ready(pieces.front().field);
                return std::make_unique<Document>(std::move(pieces), std::filesystem::path(),
                                                  scaledProgress(p, 0.7, 1.0));
            },
            [path, report] {
                return "import " + path.filename().string() + " done, a piece per label: " + importSummary(*report);
            });
        return true;
    }
    if (replaces) {  // the new document, its mesh too, made on the job's thread
        host.startDocument(
            "import " + path.filename().string(),
            [path, options, report](const Progress& p, const ModeHost::FieldReady& ready) {
                FieldImage field = importShape(path, options, *report, scaledProgress(p, 0.0, 0.7));
                ready(field);
                return std::make_unique<Document>(std::move(field), std::filesystem::path(),
                                                  scaledProgress(p, 0.7, 1.0));
            },
            [path, report] { return "import " + path.filename().string() + " done: " + importSummary(*report); });
        return true;
    }
    const CsgOperation operation =
        result == ImportDraft::Result::Union ? CsgOperation::Union : CsgOperation::Difference;
    host.startEdit({"import " + std::string(importResultName(result)) + " " + path.filename().string(),
                    [path, options, operation, report](FieldImage model, const Progress& p) {
                        combine(model, importShape(path, options, *report, p), operation);
                        return model;
                    },
                    [report] { return importSummary(*report); }});
    return true;
}

void ImportMode::drawPanel(SculptApp& app) { drawImportPanel(app, mDraft); }

nlohmann::json ImportMode::report()
{
    ImportDraft& draft = mDraft;
    const bool scan = draft.file().isScan();
    return {{"file", draft.file().path().string()},
            {"iso", scan ? draft.iso() : 0.0},
            {"otsu", scan ? draft.file().otsuThreshold(draft.options) : 0.0},
            {"result", importResultName(draft.result)},
            {"label_pieces", draft.labelPieces},
            {"preview_voxel_size", draft.file().previewVoxelSize()},
            {"preview_ms", draft.previewMs()},
            {"problem", draft.problem()},
            {"preview_triangles", mPreview.triangleCount()}};
}

}  // namespace sculpt::ui
