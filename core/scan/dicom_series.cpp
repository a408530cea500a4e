#include "core/scan/dicom_series.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/scan/vtk_image_scan.h"

#include <vtkDICOMImageReader.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// One DICOM slice: its samples and where it sits.
struct DicomSlice {
    vtkSmartPointer<vtkImageData> image;
    openvdb::Vec3d position, rowDirection, columnDirection;
    double rowSpacing = 0.0, columnSpacing = 0.0;
    std::string file;
};

DicomSlice readDicomSlice(const fs::path& file)
{
    vtkNew<vtkDICOMImageReader> reader;
    reader->SetFileName(file.string().c_str());
    DicomSlice slice;
    slice.image = runReader(reader, file.string());
    const float* p = reader->GetImagePositionPatient();
    const float* o = reader->GetImageOrientationPatient();
    const double* spacing = reader->GetPixelSpacing();
    slice.position = openvdb::Vec3d(p[0], p[1], p[2]);
    slice.rowDirection = openvdb::Vec3d(o[0], o[1], o[2]);
    slice.columnDirection = openvdb::Vec3d(o[3], o[4], o[5]);
    slice.columnSpacing = spacing[0];
    slice.rowSpacing = spacing[1];
    slice.file = file.string();
    if (slice.rowDirection.length() < 0.5 || slice.columnDirection.length() < 0.5) {
        throw InputError(file.string() + ": no image orientation (0020,0037): not an image slice");
    }
    return slice;
}

}  // namespace

ScanVolume readDicomSeries(const fs::path& dir)
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.is_regular_file()) files.push_back(entry.path());
    }
    if (files.size() < 2) throw InputError(dir.string() + ": a DICOM series needs at least two slice files");
    std::sort(files.begin(), files.end());
    std::vector<DicomSlice> slices;
    for (const auto& file : files) slices.push_back(readDicomSlice(file));
    const DicomSlice& first = slices.front();
    int dims[3];
    first.image->GetDimensions(dims);
    const openvdb::Vec3d normal = first.rowDirection.cross(first.columnDirection).unit();
    for (const DicomSlice& s : slices) {
        int d[3];
        s.image->GetDimensions(d);
        if (d[0] != dims[0] || d[1] != dims[1] || (s.rowDirection - first.rowDirection).length() > 1e-4 ||
            (s.columnDirection - first.columnDirection).length() > 1e-4 ||
            s.image->GetScalarType() != first.image->GetScalarType()) {
            throw InputError(dir.string() + ": mixed series: " + s.file + " differs from " + first.file +
                             " in size, orientation or sample type");
        }
    }
    std::sort(slices.begin(), slices.end(), [&](const DicomSlice& a, const DicomSlice& b) {
        return a.position.dot(normal) < b.position.dot(normal);
    });
    const double step = (slices[1].position - slices[0].position).dot(normal);
    if (!(step > 1e-6))
        throw InputError(dir.string() + ": two slices at the same position (" + slices[0].file + ", " + slices[1].file +
                         "): mixed series?");
    for (size_t i = 1; i < slices.size(); ++i) {
        const double gap = (slices[i].position - slices[i - 1].position).dot(normal);
        if (std::abs(gap - step) > 0.01 * step) {
            throw InputError(dir.string() + ": slices are not evenly spaced between " + slices[i - 1].file + " and " +
                             slices[i].file + " (" + formatNumber(gap) + " instead of " + formatNumber(step) +
                             "): missing slices or mixed series");
        }
    }
    vtkNew<vtkImageData> volume;
    volume->SetDimensions(dims[0], dims[1], int(slices.size()));
    volume->AllocateScalars(first.image->GetScalarType(), 1);
    const size_t sliceBytes = size_t(dims[0]) * size_t(dims[1]) * size_t(first.image->GetScalarSize());
    for (size_t k = 0; k < slices.size(); ++k) {
        std::copy_n(static_cast<const char*>(slices[k].image->GetScalarPointer()), sliceBytes,
                    static_cast<char*>(volume->GetScalarPointer()) + k * sliceBytes);
    }
    // VTK's reader flips rows (its row 0 is the last DICOM row): undo that in the placement.
    const openvdb::Vec3d x = first.rowDirection * first.columnSpacing;
    const openvdb::Vec3d y = -first.columnDirection * first.rowSpacing;
    const openvdb::Vec3d origin = slices[0].position + first.columnDirection * (first.rowSpacing * (dims[1] - 1));
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    for (int a = 0; a < 3; ++a) {
        m[0][a] = x[a];
        m[1][a] = y[a];
        m[2][a] = normal[a] * step;
        m[3][a] = origin[a];
    }
    return makeScan(volume, m, dir.string());
}

}  // namespace sculpt
