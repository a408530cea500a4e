// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/scan/kept_scan.h"
#include "core/scan/label_map_files.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/document_input.h"
#include "sculpt/cli/progress_bar.h"
#include "sculpt/session/label_export.h"

#include <CLI/CLI.hpp>

#include <memory>

namespace sculpt::cli {

namespace {

struct ExportLabelsOptions {
    DocumentInput input;
    std::string like, output;
    RunOptions run;
};

void runExportLabels(const ExportLabelsOptions& o)
{
    checkLabelMapPath(o.output);
    AtomicFile::checkTarget(o.output);
    const VdbPieces document = readPieces(o.input);
    const ScanLattice lattice = labelLattice(o.like, findKeptScan(document.companions.grids), o.input.path);
    const LabelMap map = [&] {
        ProgressBar bar("labelling");
        return exportLabels(document.pieces, lattice, o.output, bar.callback());
    }();
    const std::vector<std::string> lines = describeLabels(map);
    CommandReport report("export-labels", o.run);
    report.wrote(o.output, "labels");
    const openvdb::Coord& d = map.lattice.dims;
    report["dims"] = {d.x(), d.y(), d.z()};
    report["labels"] = nlohmann::json::array();
    for (const LabelSegment& segment : map.segments)
        report["labels"].push_back({{"label", segment.label}, {"name", segment.name}, {"samples", segment.samples}});
    report.say("wrote " + o.output + ": " + lines.front());
    for (std::size_t i = 1; i < lines.size(); ++i) report.say("  " + lines[i]);
    report.print();
}

}  // namespace

void addExportLabelsCommand(CLI::App& app)
{
    auto o = std::make_shared<ExportLabelsOptions>();
    CLI::App* cmd = app.add_subcommand(
        "export-labels", "Give a document's pieces back to the scan as a segmentation: each piece becomes a label on\n"
                         "the scan's lattice (its dimensions, spacing, origin and directions), a sample taking the\n"
                         "label of the piece whose surface holds its centre. A piece keeps the label it was imported\n"
                         "with (import --labels); the others take the smallest unused values. The format follows the\n"
                         "output's extension: .nii or .nii.gz (NIfTI-1, RAS sform and qform), .nrrd (LPS space), or\n"
                         ".seg.nrrd (3D Slicer's segmentation: each segment's name and colour too).");
    cmd->footer("Examples:\n  sculpt export-labels atlas.vdb -o atlas-edited.seg.nrrd");
    addDocumentInput(*cmd, o->input, "the .vdb document whose pieces to label");
    cmd->add_option("--like", o->like,
                    "the scan whose lattice the labels take (any scan `import` reads, or a document\n"
                    "keeping one); default: the scan the document keeps");
    cmd->add_option("-o,--output", o->output, "the label map to write (.nii, .nii.gz, .nrrd, .seg.nrrd)")->required();
    addRunOptions(*cmd, o->run);
    cmd->callback([o] { runExportLabels(*o); });
}

}  // namespace sculpt::cli
