// SculptApp: what it writes for replays and tests, the composed frame and the state report.

#include "core/field/grid_checksum.h"
#include "ui/app/sculpt_app.h"
#include "ui/status/process_memory.h"
#include "ui/window/window.h"

#include <nlohmann/json.hpp>
#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtk_glew.h>  // the OpenGL calls made here, as VTK loads them (no other GL header)

#include <fstream>
#include <iostream>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

nlohmann::json vec3Json(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

const char* promptName(Dialogs::Prompt prompt)
{
    switch (prompt) {
    case Dialogs::Prompt::New: return "new";
    case Dialogs::Prompt::Open: return "open";
    case Dialogs::Prompt::SaveAs: return "save-as";
    case Dialogs::Prompt::ExportMesh: return "export";
    case Dialogs::Prompt::SaveStrokes: return "save-strokes";
    case Dialogs::Prompt::SmoothModel: return "smooth-model";
    case Dialogs::Prompt::OffsetModel: return "offset-model";
    case Dialogs::Prompt::HollowModel: return "hollow-model";
    case Dialogs::Prompt::RemoveIslands: return "remove-islands";
    case Dialogs::Prompt::Morph: return "morph";
    case Dialogs::Prompt::MorphExport: return "morph-export";
    case Dialogs::Prompt::Target: return "target";
    case Dialogs::Prompt::Import: return "import";
    case Dialogs::Prompt::LoadScene: return "load-scene";
    case Dialogs::Prompt::SaveScene: return "save-scene";
    default: return "none";
    }
}

}  // namespace

void SculptApp::writeScreenshot(const fs::path& path)
{
    if (!mWindow.draws())
        return showError(path.string() + ": no screenshot without a window (headless: nothing is drawn)");
    const int w = mView.viewport().width(), h = mView.viewport().height();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(w, h, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, image->GetScalarPointer());  // bottom row first, as VTK
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName(path.c_str());
    writer->SetInputData(image);
    writer->Write();
    if (writer->GetErrorCode() != 0) showError(path.string() + ": cannot write the screenshot");
    else std::cout << "sculpt-ui: screenshot " << path.string() << std::endl;
}

void SculptApp::writeReport(const fs::path& path, const std::string& name)
{
    const SculptSession& session = mDocument->session();
    nlohmann::json r;
    if (!name.empty()) r["name"] = name;
    r["frame"] = mFramesDrawn;
    r["checksum"] = formatChecksum(gridChecksum(session.field().grid()));
    const openvdb::FloatGrid* mask = session.field().mask();
    r["mask_checksum"] = mask ? formatChecksum(gridChecksum(*mask)) : std::string();
    r["remeshed"] = mLastRemeshed;  // blocks the mesher re-meshed, empty candidates included
    const IncrementalMesher::Changes changes = session.mesher()->changesSince(mReportVersion);
    r["mesher_changed"] = changes.updated.size() + changes.removed.size();  // what it reports to viewers
    mReportVersion = session.mesher()->version();
    mStatus.report(r);
    mView.report(r);
    mLastRemeshed = 0;
    const std::optional<SurfaceHit> hit = pickAt(mPointer.x(), mPointer.y());
    r["pick"] =
        hit ? nlohmann::json{{"hit", true}, {"position", vec3Json(hit->position)}, {"normal", vec3Json(hit->normal)}}
            : nlohmann::json{{"hit", false}};
    r["modified"] = mDocument->modified();
    r["title"] = mDocument->title();
    r["path"] = mDocument->path().string();
    r["undo"] = mDocument->undoLabels().size();
    r["redo"] = mDocument->redoLabels().size();
    r["recovery_offered"] = mDialogs.recovery.has_value();
    r["asking_unsaved"] = mDialogs.afterUnsaved.has_value();
    r["prompt"] = promptName(mDialogs.prompt);
    r["prompt_path"] = mDialogs.path;  // the prompt's field, as the file chooser and Tab left it
    r["listed"] = mDialogs.listing.entries.size();
    r["error"] = mDialogs.error;
    const BackgroundJob* job = mJobs.job();
    r["job"] = job ? nlohmann::json{{"label", job->label()}, {"progress", job->progress()}} : nlohmann::json();
    r["last_job"] = mLastJob;
    r["previews_shown"] = mPreviewsShown;
    r["active_piece"] = mDocument->activePiece();
    r["pieces"] = nlohmann::json::array();
    for (const DocumentPiece& piece : mDocument->pieces()) {
        std::vector<double> placement(piece.look.placement.asPointer(), piece.look.placement.asPointer() + 16);
        r["pieces"].push_back({{"name", piece.look.name},
                               {"checksum", formatChecksum(gridChecksum(piece.session->field().grid()))},
                               {"visible", piece.look.visible},
                               {"placement", placement}});
    }
    r["target"] = mBrush.target.path.string();
    r["morph"] = nullptr;  // read by replays whether or not frames are on show
    r["mode"] = mMode ? nlohmann::json(mMode->name()) : nlohmann::json();  // the open mode's report's key
    if (mMode) r[mMode->name()] = mMode->report();
    r["notice"] = mDialogs.notice;
    r["radius"] = mBrush.radius;
    r["tool"] = brushToolName(mBrush.tool);
    r["tool_chosen"] = mTools.current().name();
    mTools.current().report(r);
    r["frame_times_ms"] = mMeasures.frameMs;  // since the previous report, as the next three
    r["latencies_ms"] = mMeasures.latencyMs;
    r["preview_latencies_ms"] = mMeasures.previewLatencyMs;
    r["stamps"] = mMeasures.stamps;
    r["triangles_drawn_per_frame"] = mMeasures.trianglesDrawn;
    r["peak_rss"] = peakResidentBytes();
    mMeasures = Measures();
    std::ofstream out(path, std::ios::app);
    out << r.dump() << "\n";
    if (!out) showError(path.string() + ": cannot write the report");
}

}  // namespace sculpt::ui
