// SPDX-License-Identifier: Apache-2.0
#include "core/scan/kept_scan.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/field/grid_checksum.h"
#include "core/io/metadata_seal.h"
#include "core/io/vdb_file.h"
#include "core/scan/header_text.h"
#include "core/scan/vtk_image_scan.h"

#include <openvdb/tools/Dense.h>
#include <openvdb/tools/Prune.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkType.h>

#include <cmath>

namespace sculpt {

namespace {

constexpr const char* kMetaDims = "sculpt.scan_dims";
constexpr const char* kMetaSource = "sculpt.scan_source";
constexpr const char* kMetaType = "sculpt.scan_type";
constexpr const char* kMetaIso = "sculpt.scan_iso";
constexpr const char* kMetaChecksum = "sculpt.checksum";

/// Half floats hold every integer up to 2^11 exactly.
constexpr double kExactInHalf = 2048.0;

/// Whether every sample survives being written as a half float: integers of at most 2^11.
bool exactInHalf(const ScanVolume& scan, int scalarType)
{
    if (scalarType == VTK_FLOAT || scalarType == VTK_DOUBLE) return false;
    const auto [lo, hi] = scan.range();
    return lo >= -kExactInHalf && hi <= kExactInHalf;
}

/// The scan's samples into `grid` (background voxels left out), straight from the image's own
/// type: no float copy of the whole scan is made.
void copySamples(const ScanVolume::Impl& impl, const openvdb::Coord& dims, openvdb::FloatGrid& grid)
{
    const openvdb::CoordBBox box = ScanLattice{dims}.indexBox();
    void* samples = impl.image->GetScalarPointer();
    switch (impl.image->GetScalarType()) {
        vtkTemplateMacro(openvdb::tools::copyFromDense(
            openvdb::tools::Dense<VTK_TT, openvdb::tools::LayoutXYZ>(box, static_cast<VTK_TT*>(samples)), grid, 0.0f));
    default: throw InputError(impl.source + ": unsupported sample type");
    }
}

std::string checksumOf(const openvdb::FloatGrid& grid) { return formatChecksum(gridChecksum(grid)); }

template <typename MetaT>
auto requiredMeta(const openvdb::GridBase& grid, const char* key)
{
    const auto meta = grid.getMetadata<MetaT>(key);
    if (!meta) throw InputError("the kept scan records no " + std::string(key));
    return meta->value();
}

openvdb::Mat4d affineMapOf(const openvdb::FloatGrid& grid)
{
    const openvdb::math::MapBase::ConstPtr map = grid.transform().baseMap();
    if (!map->isLinear()) throw InputError("the kept scan's transform is not affine");
    const openvdb::Mat4d m = map->getAffineMap()->getMat4();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(m[r][c])) throw InputError("the kept scan's transform holds a value that is not finite");
    const openvdb::Mat3d linear = m.getMat3();
    const double spacing = std::cbrt(std::abs(linear.det()));
    if (!(spacing >= kMinSampleSpacing)) throw InputError("the kept scan's transform flattens its lattice");
    return m;
}

}  // namespace

openvdb::FloatGrid::Ptr keptScanGrid(const ScanVolume& scan, std::optional<double> iso)
{
    const ScanVolume::Impl& impl = scan.impl();
    const openvdb::Coord dims = scan.dims();
    auto grid = openvdb::FloatGrid::create(float(scan.range().first));
    grid->setName(kKeptScanName);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(scan.worldFromIndex()));
    copySamples(impl, dims, *grid);
    openvdb::tools::prune(grid->tree());
    grid->setSaveFloatAsHalf(exactInHalf(scan, impl.image->GetScalarType()));
    grid->insertMeta(kMetaDims, openvdb::Vec3IMetadata(openvdb::Vec3i(dims.x(), dims.y(), dims.z())));
    grid->insertMeta(kMetaSource, openvdb::StringMetadata(std::filesystem::path(scan.source()).filename().string()));
    grid->insertMeta(kMetaType, openvdb::StringMetadata(impl.image->GetScalarTypeAsString()));
    if (iso) grid->insertMeta(kMetaIso, openvdb::DoubleMetadata(*iso));
    grid->insertMeta(kMetaChecksum, openvdb::StringMetadata(checksumOf(*grid)));
    sealMetadata(*grid);
    return grid;
}

bool isKeptScan(const openvdb::GridBase& grid)
{
    return grid.isType<openvdb::FloatGrid>() && grid.getMetadata<openvdb::Vec3IMetadata>(kMetaDims) != nullptr;
}

openvdb::FloatGrid::ConstPtr findKeptScan(const openvdb::GridPtrVec& grids)
{
    for (const openvdb::GridBase::Ptr& grid : grids)
        if (grid && isKeptScan(*grid)) return openvdb::gridConstPtrCast<openvdb::FloatGrid>(grid);
    return nullptr;
}

KeptScanRecord keptScanRecord(const openvdb::FloatGrid& grid)
{
    checkMetadataSeal(grid, "the kept scan");
    KeptScanRecord record;
    const openvdb::Vec3i dims = requiredMeta<openvdb::Vec3IMetadata>(grid, kMetaDims);
    if (dims.x() < 1 || dims.y() < 1 || dims.z() < 1 || ScanLattice{openvdb::Coord(dims)}.samples() > kMaxScanSamples) {
        throw InputError("the kept scan's dimensions (" + std::string(kMetaDims) + ") cannot be");
    }
    record.lattice = {openvdb::Coord(dims.x(), dims.y(), dims.z()), affineMapOf(grid)};
    if (!record.lattice.indexBox().isInside(grid.evalActiveVoxelBoundingBox()) && grid.activeVoxelCount() > 0)
        throw InputError("the kept scan holds samples outside its dimensions");
    if (requiredMeta<openvdb::StringMetadata>(grid, kMetaChecksum) != checksumOf(grid))
        throw InputError("the kept scan's samples do not match its checksum (damaged)");
    if (const auto source = grid.getMetadata<openvdb::StringMetadata>(kMetaSource)) record.source = source->value();
    if (const auto type = grid.getMetadata<openvdb::StringMetadata>(kMetaType)) record.sampleType = type->value();
    if (const auto iso = grid.getMetadata<openvdb::DoubleMetadata>(kMetaIso); iso && std::isfinite(iso->value()))
        record.iso = iso->value();
    return record;
}

ScanVolume scanOfKept(const openvdb::FloatGrid& grid, const std::string& source)
{
    const KeptScanRecord record = [&] {
        try {
            return keptScanRecord(grid);
        } catch (const InputError& e) {
            throw InputError(source + ": " + e.what());
        }
    }();
    const openvdb::Coord& dims = record.lattice.dims;
    requireMemory(record.lattice.samples() * sizeof(float), source + " (its kept scan)");
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(dims.x(), dims.y(), dims.z());
    image->AllocateScalars(VTK_FLOAT, 1);
    openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> dense(record.lattice.indexBox(),
                                                                  static_cast<float*>(image->GetScalarPointer()));
    openvdb::tools::copyToDense(grid, dense);
    return makeScan(image, record.lattice.worldFromIndex, source);
}

ScanVolume readKeptScan(const std::filesystem::path& path)
{
    const VdbDocument document = readVdbDocument(path);
    const openvdb::FloatGrid::ConstPtr kept = findKeptScan(document.companions.grids);
    if (!kept) {
        throw InputError(path.string() +
                         ": keeps no scan (it was not imported from one, or imported with --no-keep-scan)");
    }
    return scanOfKept(*kept, path.string());
}

}  // namespace sculpt
