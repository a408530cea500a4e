// SPDX-License-Identifier: Apache-2.0
#include "ui/modes/import_mode.h"

#include "core/base/text_format.h"
#include "core/field/csg_combine.h"
#include "sculpt/session/document.h"
#include "sculpt/session/shape_import.h"
#include "ui/input/input_event.h"
#include "ui/modes/mode_slot.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>

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

/// The scan or mesh at `path` read for the Import panel, with a first preview.
ImportDraft readForImport(const std::filesystem::path& path)
{
    auto file = std::make_shared<ImportPreview>(path);
    // Sensible defaults for a printable model: the largest piece only, at the file's resolution.
    ImportOptions defaults;
    defaults.largestComponent = true;
    const auto start = std::chrono::steady_clock::now();
    FieldImage first = file->surface(defaults);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return ImportDraft(file, std::move(first), ms, defaults);
}

/// Reads the scan or mesh at `path` as a job, then opens the Import panel on it, framed.
void startRead(ModeSlot& slot, const std::filesystem::path& path)
{
    Workspace& work = slot.host().workspace();
    if (work.busy()) return;
    work.autosaveNow();
    work.startJob<ImportDraft>(
        "read " + path.filename().string(), [path](const Progress&) { return readForImport(path); },
        [&slot](ImportDraft draft) {
            const openvdb::CoordBBox box = draft.preview()->grid().evalActiveVoxelBoundingBox();
            const auto& xform = draft.preview()->grid().transform();
            const openvdb::Vec3d lo = xform.indexToWorld(box.min()), hi = xform.indexToWorld(box.max());
            DocumentView& view = slot.host().view();
            slot.open(std::make_unique<ImportMode>(view.viewport().renderer(), std::move(draft)));
            view.camera().frame({lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()});
        });
}

}  // namespace

void ImportMode::addCommands(CommandRegistry& commands, ModeSlot& slot)
{
    Workspace& work = slot.host().workspace();
    commands.add({Command::Import,
                  "Import...",
                  "A scan (NIfTI, NRRD, MetaImage, DICOM) or a mesh: preview the surface, then a new document, or "
                  "union/difference with this one",
                  {{GLFW_KEY_I, kControl}},
                  [&work] { return work.waitReason(); },
                  [&slot] {
                      slot.host().dialogs().ask(Prompt::Kind::Import, {},
                                                [&slot](const std::filesystem::path& path) { startRead(slot, path); });
                  }});
    commands.add({Command::ApplyImport,
                  "Apply Import",
                  "Import with the panel's settings (a job)",
                  {},
                  [&slot] {
                      return slot.as<ImportMode>() ? std::string()
                                                   : std::string("no import is open: File > Import (Ctrl+I) opens one");
                  },
                  [&slot] { slot.accept(); }});
}

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

bool ImportMode::accept(PanelHost& host)
{
    const ImportDraft::Result result = mDraft.result;
    const bool replaces = result == ImportDraft::Result::NewDocument;
    if (replaces && !host.files().guardUnsaved(Command::Confirm)) return false;
    Workspace& work = host.workspace();
    work.autosaveNow();
    ImportOptions options = mDraft.options;
    if (!replaces) options.voxelSize = work.document().session().field().voxelSize();  // the document's lattice
    options.keepScan = replaces;  // a new document keeps its scan; a union or difference adds a shape only
    const std::filesystem::path path = mDraft.file().path();
    auto report = std::make_shared<ImportReport>();
    if (replaces && mDraft.labelPieces) {  // a piece per label, each meshed on the job's thread
        work.startDocument(
            "import " + path.filename().string() + " as pieces",
            [path, options, report](const Progress& p, const Workspace::FieldReady& ready) {
                std::vector<Piece> pieces = importLabelPieces(path, options, *report, scaledProgress(p, 0.0, 0.7));
                ready(pieces.front().field);
                auto document =
                    std::make_unique<Document>(std::move(pieces), std::filesystem::path(), scaledProgress(p, 0.7, 1.0));
                document->keepScan(report->keptScan);
                return document;
            },
            [path, report] {
                return "import " + path.filename().string() + " done, a piece per label: " + importSummary(*report);
            });
        return true;
    }
    if (replaces) {  // the new document, its mesh too, made on the job's thread
        work.startDocument(
            "import " + path.filename().string(),
            [path, options, report](const Progress& p, const Workspace::FieldReady& ready) {
                FieldImage field = importShape(path, options, *report, scaledProgress(p, 0.0, 0.7));
                ready(field);
                auto document =
                    std::make_unique<Document>(std::move(field), std::filesystem::path(), scaledProgress(p, 0.7, 1.0));
                document->keepScan(report->keptScan);
                return document;
            },
            [path, report] { return "import " + path.filename().string() + " done: " + importSummary(*report); });
        return true;
    }
    const CsgOperation operation =
        result == ImportDraft::Result::Union ? CsgOperation::Union : CsgOperation::Difference;
    work.startEdit({"import " + std::string(importResultName(result)) + " " + path.filename().string(),
                    [path, options, operation, report](FieldImage model, const Progress& p) {
                        combine(model, importShape(path, options, *report, p), operation);
                        return model;
                    },
                    [report] { return importSummary(*report); }});
    return true;
}

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
