// SPDX-License-Identifier: Apache-2.0
// The File menu's commands: new, open, save, export, strokes and the follow brush's target. Each
// prompt it opens says what OK does with the path.

#include "sculpt/session/shape_import.h"
#include "ui/input/input_event.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <GLFW/glfw3.h>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

/// Reads the file at `path` as the follow brush's target (and the ghost), as a job.
void loadTarget(PanelHost& host, const fs::path& path)
{
    Workspace& work = host.workspace();
    if (work.busy()) return;
    work.autosaveNow();
    auto warnings = std::make_shared<std::vector<std::string>>();
    work.startJob<FieldImage>(
        "load target " + path.filename().string(),
        [path, warnings](const Progress& p) { return loadShape(path, std::nullopt, *warnings, p); },
        [&host, path, warnings](FieldImage shape) {
            BrushOptions& brush = host.brush();
            brush.target = {path, std::make_shared<const FieldImage>(std::move(shape))};
            host.view().ghost().set(brush.target.shape.get());
            host.view().ghost().setShown(true);
            std::string notice =
                "target " + path.filename().string() + " loaded: O is the follow brush, H hides the ghost";
            if (!warnings->empty()) notice += " (" + warnings->front() + ")";
            host.notices().say(notice);
        });
}

/// A new document from the New dialog's shape, the brush sized to its voxels.
void newDocument(PanelHost& host)
{
    host.workspace().replace(std::make_unique<Document>(Document::create(host.dialogs().newShape)), true);
    host.brush().radius = 10.0 * host.document().session().field().voxelSize();
}

}  // namespace

void addFileCommands(CommandRegistry& commands, PanelHost& host)
{
    using K = Prompt::Kind;
    Workspace& work = host.workspace();
    DocumentFiles& files = host.files();
    Dialogs& dialogs = host.dialogs();
    const auto idle = [&work] { return work.waitReason(); };
    commands.add(
        {Command::New, "New...", "A new document from a sphere, box or torus", {{GLFW_KEY_N, kControl}}, idle, [&] {
             if (files.guardUnsaved(Command::New)) dialogs.ask(K::New, {}, [&](const fs::path&) { newDocument(host); });
         }});
    commands.add({Command::Open, "Open...", "Open a .vdb document", {{GLFW_KEY_O, kControl}}, idle, [&] {
                      if (files.guardUnsaved(Command::Open))
                          dialogs.ask(K::Open, {}, [&files](const fs::path& path) { files.open(path); });
                  }});
    commands.add({Command::Save, "Save", "Save the document", {{GLFW_KEY_S, kControl}}, nullptr, [&] {
                      if (work.document().path().empty()) host.execute(Command::SaveAs);
                      else files.saveTo(work.document().path());
                  }});
    commands.add({Command::SaveAs,
                  "Save As...",
                  "Save the document under a new name",
                  {{GLFW_KEY_S, kControl | kShift}},
                  nullptr,
                  [&] {
                      dialogs.ask(K::SaveAs, work.document().path().string(),
                                  [&files](const fs::path& path) { files.saveTo(path); });
                  }});
    commands.add({Command::ExportMesh,
                  "Export Mesh...",
                  "Write the surface as PLY, OBJ or STL",
                  {{GLFW_KEY_E, kControl}},
                  nullptr,
                  [&] {
                      dialogs.ask(K::ExportMesh, files.besideDocument(".ply", "sculpt.ply"),
                                  [&files](const fs::path& path) { files.exportMesh(path); });
                  }});
    commands.add({Command::ExportLabels,
                  "Export Segmentation...",
                  "Give the pieces back to the scan as a label map on its lattice (NIfTI, NRRD, Slicer .seg.nrrd)",
                  {{GLFW_KEY_E, kControl | kShift}},
                  [&work] {
                      return work.document().keptScan()
                                 ? std::string()
                                 : std::string("this document keeps no scan to label: `sculpt export-labels --like "
                                               "SCAN` labels another scan's lattice");
                  },
                  [&] {
                      dialogs.ask(K::ExportLabels, files.besideDocument(".seg.nrrd", "labels.seg.nrrd"),
                                  [&files](const fs::path& path) { files.exportLabels(path); });
                  }});
    commands.add(
        {Command::SaveStrokes, "Save Strokes...", "Write this session's strokes for `sculpt apply`", {}, nullptr, [&] {
             dialogs.ask(K::SaveStrokes, files.besideDocument(".strokes.json", "strokes.json"),
                         [&work](const fs::path& path) {
                             work.document().saveStrokes(path);
                             work.notices().say("saved strokes to " + path.string());
                         });
         }});
    commands.add({Command::LoadTarget,
                  "Load Target...",
                  "A document, scan or mesh for the follow brush and the morph, shown as a ghost (a job)",
                  {{GLFW_KEY_T, kControl}},
                  idle,
                  [&] {
                      dialogs.ask(K::Target, host.brush().target.path.string(),
                                  [&host](const fs::path& path) { loadTarget(host, path); });
                  }});
}

}  // namespace sculpt::ui
