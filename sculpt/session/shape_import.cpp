#include "sculpt/session/shape_import.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/base/text_format.h"
#include "core/io/mesh_import.h"
#include "core/io/vdb_file.h"
#include "core/local/speck_removal.h"
#include "core/scan/scan_to_level_set.h"

namespace sculpt {

namespace fs = std::filesystem;

namespace {

FieldImage importMesh(const fs::path& input, const ImportOptions& options, ImportReport& report,
                      const Progress& progress)
{
    if (options.iso || options.crop || options.smoothSigma > 0.0 || options.raw) {
        throw InputError(input.string() +
                         ": an iso-value, a crop box, smoothing and a raw layout apply to scans, not meshes");
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
    return meshToField(mesh, report.voxelSize, progress);
}

FieldImage importScan(const fs::path& input, const ImportOptions& options, ImportReport& report,
                      const Progress& progress)
{
    ScanVolume scan = options.raw ? readRawScan(input, *options.raw) : readScan(input);
    if (options.crop) scan = scan.cropped(*options.crop);
    if (options.smoothSigma > 0.0) scan = scan.smoothed(options.smoothSigma);
    report.kind = "scan";
    report.isoChosen = !options.iso;
    report.iso = options.iso ? *options.iso : scan.otsuThreshold();
    report.voxelSize = options.voxelSize.value_or(nativeVoxelSize(scan));
    if (auto filtered = scan.antiAliased(report.voxelSize)) {
        scan = std::move(*filtered);
        report.antiAliased = true;
    }
    return scanToLevelSet(scan, report.iso, report.voxelSize, progress);
}

}  // namespace

FieldImage importShape(const fs::path& input, const ImportOptions& options, ImportReport& report,
                       const Progress& progress)
{
    if (options.voxelSize && !(*options.voxelSize > 0.0)) {
        throw InputError("the voxel size must be a positive number (got " + formatNumber(*options.voxelSize) + ")");
    }
    // The conversion is most of the work; the cleanup the rest.
    const Progress converting = scaledProgress(progress, 0.0, options.largestComponent ? 0.8 : 1.0);
    FieldImage field = isMeshPath(input) && !options.raw ? importMesh(input, options, report, converting)
                                                         : importScan(input, options, report, converting);
    if (options.largestComponent) report.pieces = keepLargestComponent(field, scaledProgress(progress, 0.8, 1.0));
    if (const std::size_t flipped = removeSpecks(field)) {
        report.warnings.push_back("removed " + std::to_string(flipped) + " voxels of debris (shells of at most " +
                                  std::to_string(kMaxSpeckVoxels) + " voxels, too small to keep at this voxel size)");
    }
    return field;
}

FieldImage loadShape(const fs::path& input, std::optional<double> voxelSize, std::vector<std::string>& warnings,
                     const Progress& progress)
{
    if (lowerExtension(input) == ".vdb") return readFieldImage(input);
    ImportOptions options;
    options.voxelSize = voxelSize;
    ImportReport report;
    FieldImage field = importShape(input, options, report, progress);
    warnings.insert(warnings.end(), report.warnings.begin(), report.warnings.end());
    return field;
}

}  // namespace sculpt
