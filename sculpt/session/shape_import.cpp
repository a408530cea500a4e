// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/shape_import.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/io/mesh_import.h"
#include "core/io/vdb_file.h"
#include "core/local/speck_removal.h"
#include "core/mesh/field_measures.h"
#include "core/motion/surface_flows.h"
#include "core/scan/kept_scan.h"
#include "core/scan/scan_to_level_set.h"
#include "sculpt/session/label_names.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// A voxel larger than the whole shape can resolve nothing of it (and 1e30 overflows the lattice).
void refuseCoarserThan(double voxelSize, double extent, const fs::path& input, const char* kind)
{
    if (voxelSize > extent) {
        throw InputError(input.string() + ": a voxel size of " + formatNumber(voxelSize) + " is larger than the " +
                         kind + " (" + formatNumber(extent) + " across); choose a smaller voxel size");
    }
}

/// Finer voxel sizes tried for a closed mesh whose topology the chosen one changes, while the
/// mesh stays within this many voxels across (the default is 256).
constexpr double kMaxVoxelsAcrossTried = 1024.0;

/// The Euler characteristic the import ends with: after the debris is removed.
int importedEuler(FieldImage field)
{
    removeSpecks(field);
    return measureField(field).eulerCharacteristic;
}

/// A closed mesh's Euler characteristic, kept or not by its field: warns when not (thin parts
/// merged or lost), with the first of h/2, h/4, ... that keeps it.
void checkTopologyKept(const TriangleMesh& mesh, long long euler, const FieldImage& field, const fs::path& input,
                       ImportReport& report)
{
    const int imported = importedEuler(field.deepCopy());
    if (imported == euler) return;
    std::string advice =
        "no voxel size down to " + formatNumber(voxelSizeFor(mesh, kMaxVoxelsAcrossTried)) + " keeps it";
    for (double h = report.voxelSize / 2.0; h >= voxelSizeFor(mesh, kMaxVoxelsAcrossTried); h /= 2.0) {
        if (importedEuler(meshToField(mesh, h)) == euler) {
            report.topologyKeepingVoxelSize = h;
            advice = "a voxel size of " + formatNumber(h) + " keeps it";
            break;
        }
    }
    report.warnings.push_back(input.string() + ": at voxel size " + formatNumber(report.voxelSize) +
                              " the surface's topology changes (Euler characteristic " + std::to_string(euler) +
                              " becomes " + std::to_string(imported) +
                              ": parts thinner than about two voxels merge or vanish); " + advice);
}

FieldImage importMesh(const fs::path& input, const ImportOptions& options, ImportReport& report,
                      const Progress& progress)
{
    if (options.iso || options.label || options.crop || options.smoothSigma > 0.0 || options.raw) {
        throw InputError(input.string() +
                         ": an iso-value, a label, a crop box, smoothing and a raw layout apply to scans, not meshes");
    }
    const TriangleMesh mesh = readMesh(input);
    const MeshImportReport inspection = inspectMesh(mesh);
    if (!inspection.closed()) {
        report.warnings.push_back(input.string() + ": the mesh is not closed (" +
                                  std::to_string(inspection.boundaryEdges) + " open edges, " +
                                  std::to_string(inspection.nonManifoldEdges) +
                                  " non-manifold): inside and outside are guessed where it is open");
    }
    report.kind = "mesh";
    report.voxelSize = options.voxelSize.value_or(voxelSizeFor(mesh));
    refuseCoarserThan(report.voxelSize, voxelSizeFor(mesh, 1.0), input, "mesh");
    FieldImage field = meshToField(mesh, report.voxelSize, progress);
    if (inspection.closed()) checkTopologyKept(mesh, inspection.eulerCharacteristic, field, input, report);
    return field;
}

/// "0, 1, 2, ..., 48 (49 labels)": a label map's values, the first and the last.
std::string labelList(const std::vector<int>& labels)
{
    constexpr std::size_t kShown = 8;
    std::string text;
    for (std::size_t i = 0; i < labels.size() && i < kShown; ++i) text += (i ? ", " : "") + std::to_string(labels[i]);
    if (labels.size() > kShown) text += ", ..., " + std::to_string(labels.back());
    return text + " (" + std::to_string(labels.size()) + " labels)";
}

/// The values of a label map. @throws InputError naming the file when the scan holds
/// intensities, not labels.
std::vector<int> labelsOf(const ScanVolume& scan, const fs::path& input)
{
    std::vector<int> labels = scan.labels();
    if (labels.empty()) {
        throw InputError(input.string() + ": its samples are not labels (not all integers, or more than " +
                         std::to_string(ScanVolume::kMaxLabels) + " values): import it at an iso-value instead");
    }
    return labels;
}

/// The mask of `label` in a label map. @throws InputError naming the file when the scan holds
/// intensities, not labels, or no sample of that label.
ScanVolume labelMaskOf(const ScanVolume& scan, int label, const fs::path& input)
{
    const std::vector<int> labels = labelsOf(scan, input);
    if (!std::binary_search(labels.begin(), labels.end(), label)) {
        throw InputError(input.string() + ": no sample has label " + std::to_string(label) + "; its labels are " +
                         labelList(labels));
    }
    return scan.labelMask(label);
}

/// The scan as the options read it: raw or from its file, cropped; its reader's warnings reported.
ScanVolume readScanOf(const fs::path& input, const ImportOptions& options, ImportReport& report)
{
    ScanVolume scan = options.raw ? readRawScan(input, *options.raw) : readScan(input);
    report.warnings.insert(report.warnings.end(), scan.warnings().begin(), scan.warnings().end());
    return options.crop ? scan.cropped(*options.crop) : scan;
}

/// The surface of a scan (or of one label's mask) as the options ask: smoothed, at the iso-value
/// and voxel size, anti-aliased.
FieldImage scanSurface(ScanVolume scan, const fs::path& input, const ImportOptions& options, ImportReport& report,
                       const Progress& progress)
{
    if (options.voxelSize) refuseCoarserThan(*options.voxelSize, scan.worldExtent(), input, "scan");
    if (options.smoothSigma > scan.worldExtent()) {
        throw InputError(input.string() + ": a smoothing sigma of " + formatNumber(options.smoothSigma) +
                         " is wider than the scan (" + formatNumber(scan.worldExtent()) +
                         " across): it would blur everything away");
    }
    if (options.smoothSigma > 0.0) scan = scan.smoothed(options.smoothSigma);
    report.kind = "scan";
    report.isoChosen = !options.iso && !options.label;
    report.iso = scanIso(options, [&] { return scan.otsuThreshold(); });
    report.voxelSize = options.voxelSize.value_or(nativeVoxelSize(scan));
    report.twoValued = scan.twoValued();
    report.maskAntiAliased = antiAliasesMask(options, report.twoValued);
    if (auto filtered = scan.antiAliased(report.voxelSize)) {
        scan = std::move(*filtered);
        report.antiAliased = true;
    }
    if (!report.maskAntiAliased) return scanToLevelSet(scan, report.iso, report.voxelSize, progress);
    FieldImage field = scanToLevelSet(scan, report.iso, report.voxelSize, scaledProgress(progress, 0.0, 0.6));
    antiAlias(field, kAntiAliasIterations, scaledProgress(progress, 0.6, 1.0));
    return field;
}

FieldImage importScan(const fs::path& input, const ImportOptions& options, ImportReport& report,
                      const Progress& progress)
{
    if (options.label && options.iso) {
        throw InputError(input.string() + ": a label and an iso-value exclude each other (a label's surface is "
                                          "where its mask crosses 0.5)");
    }
    ScanVolume scan = readScanOf(input, options, report);
    const ScanVolume read = scan;
    if (options.label) scan = labelMaskOf(scan, *options.label, input);
    FieldImage field = scanSurface(std::move(scan), input, options, report, progress);
    if (options.keepScan)
        report.keptScan = keptScanGrid(read, options.label ? std::nullopt : std::optional(report.iso));
    return field;
}

/// The samples around one label's box: a margin of the band, the filters' reach and a voxel
/// (world widths over the finest spacing), so its surface is the one the whole scan gives.
ScanVolume aroundLabel(const ScanVolume& scan, const openvdb::CoordBBox& box, const ImportOptions& options,
                       double voxelSize)
{
    const double finest = std::min({scan.spacing(0), scan.spacing(1), scan.spacing(2)});
    const double reach = (FieldImage::kDefaultHalfWidthVoxels + 2.0) * voxelSize + 3.0 * options.smoothSigma;
    openvdb::CoordBBox around = box;
    around.expand(int(std::ceil(reach / finest)) + 1);
    around.intersect(openvdb::CoordBBox(openvdb::Coord(0), scan.dims() - openvdb::Coord(1)));
    return scan.cropped(around);
}

/// A field this small may be nothing but specks (a label of a few samples): it is copied before
/// they are removed, so that the shape itself is not.
constexpr openvdb::Index64 kSpeckSizedField = 4096;

/// Whether any voxel of the band lies inside.
bool holdsInside(const FieldImage& field)
{
    for (auto it = field.grid().cbeginValueOn(); it; ++it)
        if (*it < 0.0f) return true;
    return false;
}

/// Debris removed and, when asked, all but the largest solid piece: the end of every import. A
/// shape that is all specks at this voxel size (a label of a few samples) is kept, and said so.
void cleanUp(FieldImage& field, const ImportOptions& options, ImportReport& report, const Progress& progress)
{
    if (options.largestComponent) report.pieces = keepLargestComponent(field, progress);
    std::optional<FieldImage> whole;
    if (field.grid().activeVoxelCount() <= kSpeckSizedField) whole = field.deepCopy();
    const std::size_t flipped = removeSpecks(field);
    if (whole && !holdsInside(field)) {
        field = std::move(*whole);
        report.warnings.push_back("the shape is no bigger than a speck at voxel size " +
                                  formatNumber(field.voxelSize()) + " (at most " + std::to_string(kMaxSpeckVoxels) +
                                  " voxels): kept; a finer voxel size draws it rounder");
    } else if (flipped) {
        report.warnings.push_back("removed " + std::to_string(flipped) + " voxels of debris (shells of at most " +
                                  std::to_string(kMaxSpeckVoxels) + " voxels, too small to keep at this voxel size)");
    }
}

/// The surface of the label `options.label`, whose samples lie in `box`, cleaned up.
FieldImage labelSurface(const ScanVolume& scan, const openvdb::CoordBBox& box, const fs::path& input,
                        const ImportOptions& options, ImportReport& report, const Progress& progress)
{
    const double voxelSize = options.voxelSize.value_or(nativeVoxelSize(scan));
    const ScanVolume mask = aroundLabel(scan, box, options, voxelSize).labelMask(*options.label);
    FieldImage field = scanSurface(mask, input, options, report, scaledProgress(progress, 0.0, 0.9));
    cleanUp(field, options, report, scaledProgress(progress, 0.9, 1.0));
    return field;
}

/// A label's piece: named and coloured as the files beside the scan say, else "label N" in the
/// palette's colours from its second (the first is the clay's grey); a name taken already gets
/// the label's number.
Piece labelPiece(int label, const std::map<int, LabelLook>& looks, std::set<std::string>& names, std::size_t index,
                 FieldImage field)
{
    const auto look = looks.find(label);
    const std::string number = "label " + std::to_string(label);
    std::string name = look != looks.end() && !look->second.name.empty() ? look->second.name : number;
    if (!names.insert(name).second) names.insert(name += " (" + number + ")");
    const openvdb::Vec3f colour =
        look != looks.end() && look->second.colour ? *look->second.colour : paletteColour(index + 1);
    Piece piece{{name, colour}, std::move(field)};
    piece.label = label;
    return piece;
}

/// What a piece costs at least, however small its label: a float tree's upper nodes (32,768 and
/// 4,096 entries, about 300 KiB; more where the band straddles a node's edge), its leaves and look.
constexpr double kPieceLeastBytes = 512.0 * 1024.0;

/// A label this small (voxels of its box at the import's voxel size) is imported beside others:
/// its work is a few milliseconds, mostly OpenVDB's fixed cost per tree, which one thread cannot
/// hide, and a batch of them costs little memory at once.
constexpr double kSmallLabelVoxels = 64.0 * 64.0 * 64.0;
constexpr std::size_t kSmallLabelBatch = 64;

/// Where the batch of labels from `first` ends: one large label alone (it is parallel within),
/// else up to kSmallLabelBatch small ones in a row.
std::size_t labelBatchEnd(const ScanVolume& scan, const std::vector<std::pair<int, ScanVolume::LabelExtent>>& labels,
                          std::size_t first, double voxelSize)
{
    const auto small = [&](std::size_t i) {
        const openvdb::Coord dims = labels[i].second.box.dim();
        double voxels = 1.0;
        for (int axis = 0; axis < 3; ++axis) voxels *= std::ceil(double(dims[axis]) * scan.spacing(axis) / voxelSize);
        return voxels <= kSmallLabelVoxels;
    };
    std::size_t end = first + 1;
    if (!small(first)) return end;
    while (end < labels.size() && end - first < kSmallLabelBatch && small(end)) ++end;
    return end;
}

/// Runs `convert` and returns what it returns, making sure any refusal names the file: a message from deep in the engine
/// ("the mesh at voxel size ... needs ...") does not know it.
template <typename Convert>
auto namingInput(const fs::path& input, const Convert& convert)
{
    try {
        return convert();
    } catch (const InputError& e) {
        if (std::string(e.what()).find(input.string()) != std::string::npos) throw;
        throw InputError(input.string() + ": " + e.what(), e.remedy());
    }
}

}  // namespace

double scanIso(const ImportOptions& options, const std::function<double()>& otsu)
{
    if (options.iso) return *options.iso;
    return options.label ? 0.5 : otsu();
}

bool antiAliasesMask(const ImportOptions& options, bool twoValued)
{
    return options.antiAliasMask.value_or(twoValued || options.label.has_value());
}

FieldImage importShape(const fs::path& input, const ImportOptions& options, ImportReport& report,
                       const Progress& progress)
{
    if (options.voxelSize && !(*options.voxelSize > 0.0 && std::isfinite(*options.voxelSize))) {
        throw InputError(input.string() + ": the voxel size must be a positive number (got " +
                         formatNumber(*options.voxelSize) + ")");
    }
    // The conversion is most of the work; the cleanup the rest.
    const Progress converting = scaledProgress(progress, 0.0, options.largestComponent ? 0.8 : 1.0);
    FieldImage field = namingInput(input, [&] {
        return isMeshPath(input) && !options.raw ? importMesh(input, options, report, converting)
                                                 : importScan(input, options, report, converting);
    });
    cleanUp(field, options, report, scaledProgress(progress, 0.8, 1.0));
    return field;
}

std::vector<Piece> importLabelPieces(const fs::path& input, const ImportOptions& options, ImportReport& report,
                                     const Progress& progress)
{
    if (options.label || options.iso) {
        throw InputError(input.string() + ": every label becomes a piece; a label or an iso-value choose one surface");
    }
    if (isMeshPath(input) && !options.raw) throw InputError(input.string() + ": a mesh has no labels");
    return namingInput(input, [&] {
        const ScanVolume scan = readScanOf(input, options, report);
        labelsOf(scan, input);
        if (const double same = scan.sameNeighbourFraction(); same < kLeastLabelMapAgreement) {
            throw InputError(
                "its samples look like intensities, not labels: " + formatNumber(std::round(100.0 * same)) +
                "% of neighbouring samples off the background agree, where a label map's mostly "
                "do (regions of one label); import it at an iso-value, or one value with --label");
        }
        std::map<int, ScanVolume::LabelExtent> extents = scan.labelExtents();
        extents.erase(kBackgroundLabel);
        if (extents.empty()) throw InputError("every sample is background (label 0)");
        const std::map<int, LabelLook> looks = readLabelLooks(input, report.warnings);
        const std::vector<std::pair<int, ScanVolume::LabelExtent>> labels(extents.begin(), extents.end());
        requireMemory(double(labels.size()) * kPieceLeastBytes,
                      std::to_string(labels.size()) +
                          " labels as pieces (each at least an OpenVDB tree's upper nodes)");
        std::vector<std::optional<FieldImage>> fields(labels.size());
        std::vector<ImportReport> reports(labels.size());
        const double voxelSize = options.voxelSize.value_or(nativeVoxelSize(scan));
        for (std::size_t first = 0; first < labels.size();) {
            const std::size_t end = labelBatchEnd(scan, labels, first, voxelSize);
            const double done = double(first) / double(labels.size());
            const Progress one =
                end == first + 1 ? scaledProgress(progress, done, double(end) / double(labels.size())) : Progress();
            tbb::parallel_for(first, end, [&](std::size_t i) {
                ImportOptions labelOptions = options;
                labelOptions.label = labels[i].first;
                fields[i] = labelSurface(scan, labels[i].second.box, input, labelOptions, reports[i], one);
            });
            sculpt::report(progress, double(end) / double(labels.size()));
            first = end;
        }
        std::vector<Piece> pieces;
        std::set<std::string> names;
        for (std::size_t i = 0; i < labels.size(); ++i) {
            pieces.push_back(labelPiece(labels[i].first, looks, names, i, std::move(*fields[i])));
            for (const std::string& warning : reports[i].warnings)
                report.warnings.push_back("piece '" + pieces.back().name + "': " + warning);
        }
        reports.back().warnings = std::move(report.warnings);
        report = std::move(reports.back());
        if (options.keepScan) report.keptScan = keptScanGrid(scan, std::nullopt);
        return pieces;
    });
}

FieldImage loadShape(const fs::path& input, std::optional<double> voxelSize, std::vector<std::string>& warnings,
                     const Progress& progress)
{
    if (lowerExtension(input) == ".vdb") {
        VdbDocument document = readVdbDocument(input);
        warnings.insert(warnings.end(), document.warnings.begin(), document.warnings.end());
        return std::move(document.field);
    }
    ImportOptions options;
    options.voxelSize = voxelSize;
    ImportReport report;
    FieldImage field = importShape(input, options, report, progress);
    warnings.insert(warnings.end(), report.warnings.begin(), report.warnings.end());
    return field;
}

}  // namespace sculpt
