// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/warning_summary.h"
#include "core/io/vdb_file.h"
#include "core/mesh/field_measures.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/mesh_output.h"
#include "sculpt/cli/number_checks.h"
#include "sculpt/cli/progress_bar.h"
#include "sculpt/session/shape_import.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

struct ImportCommandOptions {
    std::string input, output, mesh;
    double iso = 0.0, voxelSize = 0.0, smooth = 0.0;
    int label = 0;
    bool autoIso = false, largest = false, antiAlias = false, labels = false, verbose = false, noKeepScan = false;
    std::vector<int> crop;
    std::vector<int> rawDims;
    std::string rawType = "uint8";
    std::vector<double> rawSpacing{1.0, 1.0, 1.0}, rawOrigin{0.0, 0.0, 0.0};
    bool rawBigEndian = false;
    std::size_t rawHeader = 0;
    CLI::Option* isoOption = nullptr;
    CLI::Option* voxelOption = nullptr;
    CLI::Option* antiAliasOption = nullptr;
    CLI::Option* labelOption = nullptr;
    RunOptions run;
};

ImportOptions toImportOptions(const ImportCommandOptions& o)
{
    ImportOptions options;
    if (o.isoOption->count()) options.iso = o.iso;
    if (o.voxelOption->count()) options.voxelSize = o.voxelSize;
    if (o.labelOption->count()) options.label = o.label;
    if (!o.crop.empty()) {
        options.crop = openvdb::CoordBBox(openvdb::Coord(o.crop[0], o.crop[1], o.crop[2]),
                                          openvdb::Coord(o.crop[3], o.crop[4], o.crop[5]));
    }
    options.smoothSigma = o.smooth;
    options.largestComponent = o.largest;
    options.keepScan = !o.noKeepScan;
    if (o.antiAliasOption->count()) options.antiAliasMask = o.antiAlias;
    if (!o.rawDims.empty()) {
        RawLayout raw;
        raw.dims = openvdb::Coord(o.rawDims[0], o.rawDims[1], o.rawDims[2]);
        raw.type = o.rawType;
        raw.spacing = openvdb::Vec3d(o.rawSpacing[0], o.rawSpacing[1], o.rawSpacing[2]);
        raw.origin = openvdb::Vec3d(o.rawOrigin[0], o.rawOrigin[1], o.rawOrigin[2]);
        raw.bigEndian = o.rawBigEndian;
        raw.headerBytes = o.rawHeader;
        options.raw = raw;
    }
    return options;
}

/// The import's warnings on stderr: each kind a few times, every one with --verbose.
void printWarnings(const std::vector<std::string>& warnings, bool verbose)
{
    for (const std::string& warning : verbose ? warnings : summarisedWarnings(warnings))
        std::cerr << "sculpt: warning: " << warning << "\n";
}

/// The document's other grids: the scan, unless --no-keep-scan (or a mesh).
VdbCompanions keptScanOf(const ImportReport& report)
{
    VdbCompanions companions;
    if (report.keptScan) companions.grids.push_back(report.keptScan);
    return companions;
}

/// A solid's measures, for the report's JSON and its prose ("volume V, area A, C components").
nlohmann::json solidJson(const FieldMeasures& m)
{
    return {{"volume", m.volume}, {"area", m.area}, {"components", m.components}};
}
std::string describeSolid(const FieldMeasures& m)
{
    std::ostringstream text;
    text << "volume " << m.volume << ", area " << m.area << ", " << m.components << " components";
    return text.str();
}

/// `--labels`: a piece per label, written as one document.
void runLabelsImport(const ImportCommandOptions& o)
{
    ImportReport report;
    const std::vector<Piece> pieces = [&] {
        ProgressBar bar("importing labels");
        return importLabelPieces(o.input, toImportOptions(o), report, bar.callback());
    }();
    printWarnings(report.warnings, o.verbose);
    writeVdbPieces(pieces, o.output, keptScanOf(report));
    CommandReport out("import", o.run);
    out.wrote(o.output, "document");
    out["kind"] = "labels";
    out["voxel_size"] = report.voxelSize;
    out["anti_aliased"] = report.maskAntiAliased;
    out["pieces"] = nlohmann::json::array();
    std::ostringstream head;
    head << "imported " << o.input << " (a label map): " << pieces.size() << " pieces, voxel size " << report.voxelSize
         << (report.maskAntiAliased ? ", anti-aliased" : "");
    out.say(head.str());
    out.say("wrote " + o.output + ":");
    for (const Piece& piece : pieces) {
        const FieldMeasures m = measureField(piece.field);
        nlohmann::json entry = solidJson(m);
        entry["name"] = piece.name;
        out["pieces"].push_back(entry);
        out.say("  '" + piece.name + "': " + describeSolid(m));
    }
    writePiecesMeshes(pieces, o.mesh, out);
    out.print();
}

void runImport(const ImportCommandOptions& o)
{
    AtomicFile::checkTarget(o.output);
    checkMeshOutput(o.mesh);
    if (o.labels) return runLabelsImport(o);
    ImportReport report;
    const FieldImage field = [&] {
        ProgressBar bar("importing");
        return importShape(o.input, toImportOptions(o), report, bar.callback());
    }();
    printWarnings(report.warnings, o.verbose);
    writeFieldImage(field, o.output, keptScanOf(report));
    const FieldMeasures m = measureField(field);
    CommandReport out("import", o.run);
    out.wrote(o.output, "document");
    out["kind"] = report.kind;
    out["iso"] = report.kind == "scan" && !o.labelOption->count() ? nlohmann::json(report.iso) : nlohmann::json();
    out["iso_chosen"] = report.isoChosen;
    out["voxel_size"] = report.voxelSize;
    out["anti_aliased"] = report.maskAntiAliased;
    const nlohmann::json solid = solidJson(m);
    for (const auto& [key, value] : solid.items()) out[key] = value;
    std::ostringstream head;
    head << "imported " << o.input << " (" << report.kind << ")";
    if (o.labelOption->count()) head << " label " << o.label;
    else if (report.kind == "scan") head << " at iso-value " << report.iso << (report.isoChosen ? " (Otsu)" : "");
    head << ", voxel size " << report.voxelSize << (report.antiAliased ? " (samples low-pass filtered for it)" : "");
    if (o.largest) {
        head << ", " << report.pieces.islandsDropped << " islands dropped, " << report.pieces.cavitiesFilled
             << " cavities filled";
    }
    out.say(head.str());
    if (report.maskAntiAliased) {
        out.say(report.twoValued ? "the samples take two values only (a mask): its voxel terraces were "
                                   "anti-aliased (--no-antialias keeps them)"
                                 : "the surface's voxel terraces were anti-aliased");
    }
    out.say("wrote " + o.output + ": " + describeSolid(m));
    writeMeshOutput(field, o.mesh, out);
    out.print();
}

}  // namespace

void addImportCommand(CLI::App& app)
{
    auto o = std::make_shared<ImportCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "import", "Turn a medical scan or a mesh into an editable document.\n"
                  "Scans: NIfTI (.nii, .nii.gz), NRRD (.nrrd, .nhdr), MetaImage (.mha, .mhd), INRIMAGE\n"
                  "(.inr, .inr.gz), DICOM (a directory of slices, one slice file to pick its series,\n"
                  "or a multi-frame file; compressed too), raw samples (--raw-dims ...), or the scan a\n"
                  "document keeps (.vdb). The surface is where the samples cross the iso-value (inside:\n"
                  "above it); spacing, origin and orientation are kept, so the surface sits where the\n"
                  "scan says, in LPS millimetres. The document keeps the scan (--no-keep-scan: not).\n"
                  "Meshes: .obj, .ply, .stl, .off; an open mesh imports with a warning.");
    cmd->footer("Examples:\n  sculpt import /usr/share/mricron/templates/ch2better.nii.gz --voxel-size 0.5 -o "
                "brain.vdb\n  sculpt import atlas.nii.gz --labels -o atlas.vdb   (a piece per label)\n  sculpt import "
                "part.stl --voxel-size 0.2 -o part.vdb");
    cmd->add_option("input", o->input, "the scan file, DICOM directory or slice, or mesh file")->required();
    cmd->add_flag("--verbose", o->verbose,
                  "print every warning (a label map's pieces can give hundreds alike: without it, each kind is\n"
                  "printed three times and then counted)");
    o->isoOption = cmd->add_option("--iso", o->iso, "the surface's sample value (scans)");
    cmd->add_flag("--auto-iso", o->autoIso, "choose the iso-value by Otsu's method (the default without --iso)")
        ->excludes(o->isoOption);
    o->labelOption = cmd->add_option("--label", o->label,
                                     "a label map (a segmentation: integer samples, one value per structure): the\n"
                                     "surface around the samples of this label, anti-aliased")
                         ->excludes(o->isoOption);
    cmd->add_flag("--labels", o->labels,
                  "a label map: one piece per label (but 0, the background), each anti-aliased, named\n"
                  "and coloured as 3D Slicer's segment fields (.seg.nrrd) or MRIcron's atlas.nii.txt and\n"
                  ".lut beside it say, else 'label N'; --mesh then writes a file per piece (or one OBJ)")
        ->excludes(o->isoOption)
        ->excludes(o->labelOption);
    o->voxelOption = cmd->add_option(
        "--voxel-size", o->voxelSize,
        "voxel size of the document (default: the scan's smallest spacing; a mesh's longest side / 256)");
    cmd->add_option("--crop", o->crop, "scan sample box x0,y0,z0,x1,y1,z1 (indices, inclusive)")
        ->delimiter(',')
        ->expected(6);
    cmd->add_option("--smooth", o->smooth, "Gaussian pre-smoothing of noisy scans: sigma in world units")
        ->check(nonNegativeNumber());
    o->antiAliasOption =
        cmd->add_flag("--antialias,!--no-antialias", o->antiAlias,
                      "smooth away the voxel terraces of a surface cut from binary data, keeping every sample on\n"
                      "its side of it (Whitaker's constrained flow); the default for scans of two values (masks)");
    cmd->add_flag("--largest-component", o->largest,
                  "keep only the largest solid piece: drops islands, fills closed cavities");
    cmd->add_option("--raw-dims", o->rawDims, "raw input: samples along x,y,z")->delimiter(',')->expected(3);
    cmd->add_option("--raw-type", o->rawType, "raw input: uint8, int8, uint16, int16, uint32, int32, float32, float64")
        ->capture_default_str();
    cmd->add_option("--raw-spacing", o->rawSpacing, "raw input: voxel size along x,y,z")->delimiter(',')->expected(3);
    cmd->add_option("--raw-origin", o->rawOrigin, "raw input: world position of the first sample")
        ->delimiter(',')
        ->expected(3);
    cmd->add_flag("--raw-big-endian", o->rawBigEndian, "raw input: most significant byte first");
    cmd->add_option("--raw-header", o->rawHeader, "raw input: bytes to skip before the samples");
    cmd->add_flag("--no-keep-scan", o->noKeepScan,
                  "do not keep the scan's samples in the document (kept by default, so the window shows\n"
                  "its slices and `sculpt import DOC.vdb --iso V` imports it again at another iso-value)");
    cmd->add_option("-o,--output", o->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, o->mesh);
    addRunOptions(*cmd, o->run);
    cmd->callback([o] { runImport(*o); });
}

}  // namespace sculpt::cli
