// SPDX-License-Identifier: Apache-2.0
#include "core/scan/dicom_series.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/scan/dicom_directory.h"
#include "core/scan/dicom_file.h"
#include "core/scan/vtk_image_scan.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr double kGapStep = 1.5;         // a step this many times the median is a missing slice
constexpr double kEvenTolerance = 1e-3;  // steps this close to the mean count as even (relative)

/// One frame of one file, and how deep it sits along the slice normal.
struct Slice {
    const DicomFrames* file = nullptr;
    int frame = 0;
    double depth = 0.0;
    const openvdb::Vec3d& position() const { return file->positions[std::size_t(frame)]; }
    std::string name() const
    {
        return file->positions.size() > 1 ? file->file + " frame " + std::to_string(frame + 1) : file->file;
    }
};

/// The listing's note as the scan's warnings.
std::vector<std::string> notes(const fs::path& dir, const DicomDirectoryListing& listing)
{
    std::string note = listingNote(dir, listing);
    return note.empty() ? std::vector<std::string>{} : std::vector<std::string>{std::move(note)};
}

/// Refuses a directory holding several series: which one is meant is for the user to say.
void requireOneSeries(const std::vector<DicomFrames>& files, const fs::path& dir)
{
    std::map<std::string, int> counts;
    for (const DicomFrames& f : files) ++counts[f.seriesUid];
    if (counts.size() < 2) return;
    std::string list;
    for (const auto& [uid, count] : counts)
        list += (list.empty() ? "" : ", ") + (uid.empty() ? "no UID" : uid) + " (" + std::to_string(count) + " files)";
    throw InputError(dir.string() + ": " + std::to_string(counts.size()) + " series in one directory: " + list +
                     "; open one slice file of the series you want");
}

void requireSameGeometry(const std::vector<DicomFrames>& files, const fs::path& dir)
{
    const DicomFrames& first = files.front();
    for (const DicomFrames& f : files) {
        const int* a = f.samples->GetDimensions();
        const int* b = first.samples->GetDimensions();
        if (a[0] != b[0] || a[1] != b[1] || (f.rowDirection - first.rowDirection).length() > 1e-4 ||
            (f.columnDirection - first.columnDirection).length() > 1e-4 ||
            std::abs(f.rowSpacing - first.rowSpacing) > 1e-4 * first.rowSpacing ||
            std::abs(f.columnSpacing - first.columnSpacing) > 1e-4 * first.columnSpacing) {
            throw InputError(dir.string() + ": mixed series: " + f.file + " differs from " + first.file +
                             " in size, orientation or pixel spacing");
        }
    }
}

/// Every frame of every file, sorted along the slice normal.
std::vector<Slice> sortedSlices(const std::vector<DicomFrames>& files, const openvdb::Vec3d& normal)
{
    std::vector<Slice> slices;
    for (const DicomFrames& f : files) {
        for (std::size_t k = 0; k < f.positions.size(); ++k) slices.push_back({&f, int(k), f.positions[k].dot(normal)});
    }
    std::stable_sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) { return a.depth < b.depth; });
    return slices;
}

double median(std::vector<double> values)
{
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
    return values[values.size() / 2];
}

/// Refuses steps that are not jitter: two slices at one place, a slice missing (a step of about
/// twice the usual), or slices of another series in between (a step far shorter than the usual).
void requireNoGaps(const std::vector<Slice>& slices, const fs::path& source)
{
    std::vector<double> steps;
    for (std::size_t i = 1; i < slices.size(); ++i) steps.push_back(slices[i].depth - slices[i - 1].depth);
    const double usual = median(steps);
    for (std::size_t i = 1; i < slices.size(); ++i) {
        const double step = steps[i - 1];
        const std::string between = slices[i - 1].name() + " and " + slices[i].name();
        if (!(step > 1e-6 * std::max(1.0, usual)))
            throw InputError(source.string() + ": two slices at the same position (" + between + "): mixed series?");
        if (step > kGapStep * usual || step < usual / kGapStep) {
            throw InputError(source.string() + ": slices are " + formatNumber(step) + " apart between " + between +
                             " where the series' usual step is " + formatNumber(usual) +
                             (step > usual ? ": missing slices" : ": mixed series?"));
        }
    }
}

/// The samples of every slice, copied as they are (even spacing, one sample type).
vtkSmartPointer<vtkImageData> stacked(const std::vector<Slice>& slices)
{
    const vtkSmartPointer<vtkImageData>& first = slices.front().file->samples;
    const int* d = first->GetDimensions();
    auto volume = vtkSmartPointer<vtkImageData>::New();
    volume->SetDimensions(d[0], d[1], int(slices.size()));
    volume->AllocateScalars(first->GetScalarType(), 1);
    const std::size_t sliceBytes = std::size_t(d[0]) * std::size_t(d[1]) * std::size_t(first->GetScalarSize());
    for (std::size_t k = 0; k < slices.size(); ++k) {
        const char* from = static_cast<const char*>(slices[k].file->samples->GetScalarPointer()) +
                           std::size_t(slices[k].frame) * sliceBytes;
        std::copy_n(from, sliceBytes, static_cast<char*>(volume->GetScalarPointer()) + k * sliceBytes);
    }
    return volume;
}

/// Float samples at evenly spaced depths from the first slice to the last, each interpolated
/// linearly between the two slices around it: every slice keeps its own position.
vtkSmartPointer<vtkImageData> resampledEvenly(const std::vector<Slice>& slices)
{
    const int* d = slices.front().file->samples->GetDimensions();
    const vtkIdType perSlice = vtkIdType(d[0]) * d[1];
    auto volume = vtkSmartPointer<vtkImageData>::New();
    volume->SetDimensions(d[0], d[1], int(slices.size()));
    volume->AllocateScalars(VTK_FLOAT, 1);
    float* out = static_cast<float*>(volume->GetScalarPointer());
    const double step = (slices.back().depth - slices.front().depth) / double(slices.size() - 1);
    std::size_t below = 0;
    for (std::size_t k = 0; k < slices.size(); ++k) {
        const double depth = slices.front().depth + step * double(k);
        while (below + 2 < slices.size() && slices[below + 1].depth <= depth) ++below;
        const Slice& a = slices[below];
        const Slice& b = slices[below + 1];
        const double w = std::clamp((depth - a.depth) / (b.depth - a.depth), 0.0, 1.0);
        vtkDataArray* from = a.file->samples->GetPointData()->GetScalars();
        vtkDataArray* to = b.file->samples->GetPointData()->GetScalars();
        for (vtkIdType i = 0; i < perSlice; ++i) {
            const double lo = from->GetTuple1(a.frame * perSlice + i), hi = to->GetTuple1(b.frame * perSlice + i);
            out[vtkIdType(k) * perSlice + i] = float(lo + w * (hi - lo));
        }
    }
    return volume;
}

/// How far the steps are from even, relative to the mean step.
std::pair<double, double> stepRange(const std::vector<Slice>& slices)
{
    double lo = slices[1].depth - slices[0].depth, hi = lo;
    for (std::size_t i = 2; i < slices.size(); ++i) {
        lo = std::min(lo, slices[i].depth - slices[i - 1].depth);
        hi = std::max(hi, slices[i].depth - slices[i - 1].depth);
    }
    return {lo, hi};
}

ScanVolume assemble(const std::vector<DicomFrames>& files, const fs::path& source, std::vector<std::string> warnings)
{
    requireSameGeometry(files, source);
    const DicomFrames& first = files.front();
    const openvdb::Vec3d normal = first.rowDirection.cross(first.columnDirection).unit();
    const std::vector<Slice> slices = sortedSlices(files, normal);
    if (slices.size() < 2) throw InputError(source.string() + ": a DICOM series needs at least two slices");
    requireNoGaps(slices, source);
    const double mean = (slices.back().depth - slices.front().depth) / double(slices.size() - 1);
    const auto [shortest, longest] = stepRange(slices);
    const bool even = longest - shortest <= kEvenTolerance * mean;
    const bool oneType = std::all_of(files.begin(), files.end(), [&](const DicomFrames& f) {
        return f.samples->GetScalarType() == first.samples->GetScalarType();
    });
    const int* d = first.samples->GetDimensions();
    const double bytesPerSample = std::max(4, first.samples->GetScalarSize());
    requireMemory(double(d[0]) * d[1] * double(slices.size()) * bytesPerSample,
                  source.string() + " (assembling the series)");
    if (!even) {
        warnings.push_back(source.string() + ": the slices are " + formatNumber(shortest) + " to " +
                           formatNumber(longest) + " apart: each is placed at its own position (resampled to " +
                           formatNumber(mean) + " apart)");
    }
    vtkSmartPointer<vtkImageData> volume = even && oneType ? stacked(slices) : resampledEvenly(slices);
    // Index (i, j, k) is column i, row j, slice k; the third axis follows the slices' positions
    // (not just the normal), so a tilted gantry's sheared stack lands where it was.
    const openvdb::Vec3d x = first.rowDirection * first.columnSpacing;
    const openvdb::Vec3d y = first.columnDirection * first.rowSpacing;
    const openvdb::Vec3d z = (slices.back().position() - slices.front().position()) / double(slices.size() - 1);
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    for (int a = 0; a < 3; ++a) {
        m[0][a] = x[a];
        m[1][a] = y[a];
        m[2][a] = z[a];
        m[3][a] = slices.front().position()[a];
    }
    return makeScan(volume, m, source.string(), std::move(warnings));
}

}  // namespace

bool isDicomFile(const fs::path& path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".dcm" || ext == ".dicom" || ext == ".ima";
}

ScanVolume readDicomSeries(const fs::path& path)
{
    std::vector<DicomFrames> files;
    if (fs::is_directory(path)) {
        const DicomDirectoryListing listing = listDicomDirectory(path);
        for (const fs::path& file : listing.images) files.push_back(readDicomFile(file));
        if (files.empty()) throw InputError(path.string() + ": no DICOM images in the directory");
        requireOneSeries(files, path);
        return assemble(files, path, notes(path, listing));
    }
    DicomFrames chosen = readDicomFile(path);
    if (chosen.positions.size() > 1) {
        files.push_back(std::move(chosen));
        return assemble(files, path, {});
    }
    // One slice: the series it belongs to, from its directory.
    const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    const DicomDirectoryListing listing = listDicomDirectory(dir);
    for (const fs::path& file : listing.images) {
        DicomFrames slice = fs::equivalent(file, path) ? chosen : readDicomFile(file);
        if (slice.seriesUid == chosen.seriesUid) files.push_back(std::move(slice));
    }
    return assemble(files, dir, notes(dir, listing));
}

}  // namespace sculpt
