// SPDX-License-Identifier: Apache-2.0
#include "core/scan/vtk_image_scan.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/io/vtk_error_catcher.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace sculpt {

namespace {

/// The last line of a VTK error message, without VTK's file/line prefix.
std::string cleanMessage(std::string text)
{
    // vtkImageReader's word for a file shorter than its header says.
    if (text.find("File operation failed") != std::string::npos)
        return "truncated: the file holds fewer samples than its header declares";
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    const auto colon = text.rfind(": ");
    if (colon != std::string::npos && text.find("vtk") != std::string::npos) text = text.substr(colon + 2);
    return text;
}

}  // namespace

vtkSmartPointer<vtkImageData> runReader(vtkImageReader2* reader, const std::string& source,
                                        const std::vector<std::string>& tolerated,
                                        std::vector<std::string>* toleratedSeen)
{
    const VtkErrorCatcher catcher(reader, /*warningsToo=*/true, tolerated);
    reader->UpdateInformation();
    if (catcher.caught()) throw InputError(source + ": " + cleanMessage(catcher.message()));
    int extent[6];
    reader->GetDataExtent(extent);
    std::array<long long, 3> dims{};
    for (int a = 0; a < 3; ++a) dims[size_t(a)] = (long long)extent[2 * a + 1] - extent[2 * a] + 1;
    if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1) throw InputError(source + ": the header gives no samples");
    const double voxels = double(dims[0]) * double(dims[1]) * double(dims[2]);
    const int bytesPerSample = std::max(1, vtkDataArray::GetDataTypeSize(reader->GetDataScalarType())) *
                               std::max(1, reader->GetNumberOfScalarComponents());
    if (voxels > double(1LL << 40)) {
        throw InputError(source + ": the header claims " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) +
                         " x " + std::to_string(dims[2]) + " samples: not a real scan");
    }
    requireMemory(voxels * bytesPerSample * 1.5, source + " (" + std::to_string(dims[0]) + " x " +
                                                     std::to_string(dims[1]) + " x " + std::to_string(dims[2]) +
                                                     " samples)");
    reader->Update();
    if (catcher.caught()) throw InputError(source + ": " + cleanMessage(catcher.message()));
    vtkSmartPointer<vtkImageData> image = reader->GetOutput();
    if (!image || !image->GetPointData()->GetScalars() || image->GetNumberOfPoints() != vtkIdType(voxels)) {
        throw InputError(source + ": the samples could not be read (truncated or corrupt file?)");
    }
    if (image->GetNumberOfScalarComponents() != 1) {
        throw InputError(source + ": " + std::to_string(image->GetNumberOfScalarComponents()) +
                         " values per voxel (colour or vector data); a scan has one");
    }
    if (toleratedSeen) *toleratedSeen = catcher.tolerated();
    return image;
}

openvdb::Mat4d placement(vtkImageData* image, vtkMatrix4x4* orientation)
{
    double origin[3], spacing[3];
    image->GetOrigin(origin);
    image->GetSpacing(spacing);
    openvdb::Mat4d local = openvdb::Mat4d::identity();  // row-vector convention: p' = p * M
    for (int a = 0; a < 3; ++a) {
        local[a][a] = spacing[a];
        local[3][a] = origin[a];
    }
    if (!orientation) return local;
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) m[c][r] = orientation->GetElement(r, c);  // VTK is column-vector
    }
    return local * m;
}

ScanVolume makeScan(vtkSmartPointer<vtkImageData> image, openvdb::Mat4d worldFromIndex, const std::string& source,
                    std::vector<std::string> warnings)
{
    int extent[6];
    image->GetExtent(extent);
    const openvdb::Vec3d shift = worldFromIndex.transform3x3(openvdb::Vec3d(extent[0], extent[2], extent[4]));
    image->SetExtent(0, extent[1] - extent[0], 0, extent[3] - extent[2], 0, extent[5] - extent[4]);
    worldFromIndex.setTranslation(worldFromIndex.getTranslation() + shift);
    auto impl = std::make_shared<ScanVolume::Impl>();
    impl->image = image;
    impl->worldFromIndex = worldFromIndex;
    impl->source = source;
    impl->warnings = std::move(warnings);
    const auto [lo, hi] = ScanVolume(impl).range();
    if (!std::isfinite(lo) || !std::isfinite(hi)) throw InputError(source + ": samples are not finite numbers");
    return ScanVolume(impl);
}

}  // namespace sculpt
