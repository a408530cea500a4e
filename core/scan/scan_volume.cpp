#include "core/scan/scan_volume.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/io/vtk_error_catcher.h"

#include <vtkDICOMImageReader.h>
#include <vtkExtractVOI.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkImageReader2.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkMetaImageReader.h>
#include <vtkNIFTIImageHeader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkNrrdReader.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace sculpt {

namespace fs = std::filesystem;

struct ScanVolume::Impl {
    vtkSmartPointer<vtkImageData> image;  // extent starts at (0, 0, 0)
    openvdb::Mat4d worldFromIndex = openvdb::Mat4d::identity();
    std::string source;
};

namespace {

/// The last line of a VTK error message, without VTK's file/line prefix.
std::string cleanMessage(std::string text)
{
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    const auto colon = text.rfind(": ");
    if (colon != std::string::npos && text.find("vtk") != std::string::npos) text = text.substr(colon + 2);
    return text;
}

/// Runs a configured reader: header first (dimensions checked and memory reserved before the
/// samples are allocated), then the samples; any error the reader reports becomes an InputError.
vtkSmartPointer<vtkImageData> runReader(vtkImageReader2* reader, const std::string& source)
{
    vtkObject::GlobalWarningDisplayOff();
    vtkNew<VtkErrorCatcher> catcher;
    reader->AddObserver(vtkCommand::ErrorEvent, catcher);
    reader->AddObserver(vtkCommand::WarningEvent, catcher);
    reader->UpdateInformation();
    if (!catcher->message.empty()) throw InputError(source + ": " + cleanMessage(catcher->message));
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
    if (!catcher->message.empty()) throw InputError(source + ": " + cleanMessage(catcher->message));
    vtkSmartPointer<vtkImageData> image = reader->GetOutput();
    if (!image || !image->GetPointData()->GetScalars() || image->GetNumberOfPoints() != vtkIdType(voxels)) {
        throw InputError(source + ": the samples could not be read (truncated or corrupt file?)");
    }
    if (image->GetNumberOfScalarComponents() != 1) {
        throw InputError(source + ": " + std::to_string(image->GetNumberOfScalarComponents()) +
                         " values per voxel (colour or vector data); a scan has one");
    }
    return image;
}

/// index -> world for a VTK image: world = M (origin + ijk * spacing), M a 4x4 (or identity).
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

/// Moves the extent to start at zero (readers may start elsewhere), keeping world placement.
ScanVolume makeScan(vtkSmartPointer<vtkImageData> image, openvdb::Mat4d worldFromIndex, const std::string& source)
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
    const auto [lo, hi] = ScanVolume(impl).range();
    if (!std::isfinite(lo) || !std::isfinite(hi)) throw InputError(source + ": samples are not finite numbers");
    return ScanVolume(impl);
}

ScanVolume readNifti(const fs::path& path)
{
    vtkNew<vtkNIFTIImageReader> reader;
    reader->SetFileName(path.string().c_str());
    vtkSmartPointer<vtkImageData> image = runReader(reader, path.string());
    // VTK fills a short uncompressed file with zeros without a word: check its length.
    if (lowerExtension(path) == ".nii") {
        const double needed = double(reader->GetNIFTIHeader()->GetVoxOffset()) +
                              double(image->GetNumberOfPoints()) * image->GetScalarSize();
        if (double(fs::file_size(path)) < needed) {
            throw InputError(path.string() + ": " + std::to_string(fs::file_size(path)) +
                             " bytes, but the header needs " + formatNumber(needed) + " (truncated file)");
        }
    }
    vtkMatrix4x4* orientation = reader->GetSFormMatrix() ? reader->GetSFormMatrix() : reader->GetQFormMatrix();
    // NIfTI scales stored values: value = slope * stored + intercept (slope 0 means none).
    const double slope = reader->GetRescaleSlope(), intercept = reader->GetRescaleIntercept();
    if ((slope != 0.0 && slope != 1.0) || intercept != 0.0) {
        vtkDataArray* scalars = image->GetPointData()->GetScalars();
        vtkNew<vtkFloatArray> scaled;
        scaled->SetNumberOfValues(scalars->GetNumberOfTuples());
        for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i) {
            scaled->SetValue(i, float((slope == 0.0 ? 1.0 : slope) * scalars->GetTuple1(i) + intercept));
        }
        image->GetPointData()->SetScalars(scaled);
    }
    return makeScan(image, placement(image, orientation), path.string());
}

template <typename ReaderT>
ScanVolume readWithDirection(const fs::path& path)
{
    vtkNew<ReaderT> reader;
    reader->SetFileName(path.string().c_str());
    vtkSmartPointer<vtkImageData> image = runReader(reader, path.string());
    vtkNew<vtkMatrix4x4> direction;  // the image's direction cosines, if the reader set them
    const double* d = image->GetDirectionMatrix()->GetData();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) direction->SetElement(r, c, d[3 * r + c]);
    }
    // Placement already includes the origin; rotate about it.
    double origin[3];
    image->GetOrigin(origin);
    image->SetOrigin(0.0, 0.0, 0.0);
    openvdb::Mat4d m = placement(image, direction);
    m.setTranslation(openvdb::Vec3d(origin[0], origin[1], origin[2]));
    return makeScan(image, m, path.string());
}

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

/// A directory of DICOM slices of one series: sorted along the slice normal, checked for equal
/// sizes and orientation, even spacing and no gaps, stacked into one volume.
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

int vtkTypeOf(const std::string& type)
{
    static const std::map<std::string, int> types{{"uint8", VTK_UNSIGNED_CHAR},   {"int8", VTK_SIGNED_CHAR},
                                                  {"uint16", VTK_UNSIGNED_SHORT}, {"int16", VTK_SHORT},
                                                  {"uint32", VTK_UNSIGNED_INT},   {"int32", VTK_INT},
                                                  {"float32", VTK_FLOAT},         {"float64", VTK_DOUBLE}};
    const auto found = types.find(type);
    if (found == types.end()) {
        throw InputError("unknown sample type \"" + type +
                         "\" (expected uint8, int8, uint16, int16, uint32, int32, float32 or float64)");
    }
    return found->second;
}

template <typename T>
void copyRow(const void* src, size_t count, float* out)
{
    const T* p = static_cast<const T*>(src);
    for (size_t i = 0; i < count; ++i) out[i] = float(p[i]);
}

/// Trilinear interpolation in the samples of a dims-sized lattice; an axis of one sample has
/// stride 0, so its single layer is read for both corners.
template <typename T>
void sampleTrilinear(const void* src, const openvdb::Coord& dims, const openvdb::Vec3d* points, size_t count,
                     float outside, float* out)
{
    const T* data = static_cast<const T*>(src);
    const size_t step[3] = {1, size_t(dims.x()), size_t(dims.x()) * size_t(dims.y())};
    size_t stride[3];
    for (int a = 0; a < 3; ++a) stride[a] = dims[a] > 1 ? step[a] : 0;
    for (size_t n = 0; n < count; ++n) {
        const openvdb::Vec3d& p = points[n];
        bool inside = true;
        for (int a = 0; a < 3; ++a) inside = inside && p[a] >= 0.0 && p[a] <= dims[a] - 1;
        if (!inside) {
            out[n] = outside;
            continue;
        }
        size_t base = 0;
        double f[3];
        for (int a = 0; a < 3; ++a) {
            const int i = std::min(int(p[a]), std::max(dims[a] - 2, 0));
            f[a] = p[a] - i;
            base += size_t(i) * step[a];
        }
        const auto at = [&](int dx, int dy, int dz) {
            return double(data[base + dx * stride[0] + dy * stride[1] + dz * stride[2]]);
        };
        const double c00 = at(0, 0, 0) + f[0] * (at(1, 0, 0) - at(0, 0, 0)),
                     c10 = at(0, 1, 0) + f[0] * (at(1, 1, 0) - at(0, 1, 0));
        const double c01 = at(0, 0, 1) + f[0] * (at(1, 0, 1) - at(0, 0, 1)),
                     c11 = at(0, 1, 1) + f[0] * (at(1, 1, 1) - at(0, 1, 1));
        const double c0 = c00 + f[1] * (c10 - c00), c1 = c01 + f[1] * (c11 - c01);
        out[n] = float(c0 + f[2] * (c1 - c0));
    }
}

}  // namespace

ScanVolume::ScanVolume(std::shared_ptr<const Impl> impl) : mImpl(std::move(impl)) {}

openvdb::Coord ScanVolume::dims() const
{
    int d[3];
    mImpl->image->GetDimensions(d);
    return openvdb::Coord(d[0], d[1], d[2]);
}

const openvdb::Mat4d& ScanVolume::worldFromIndex() const { return mImpl->worldFromIndex; }

std::pair<double, double> ScanVolume::range() const
{
    double r[2];
    mImpl->image->GetPointData()->GetScalars()->GetRange(r);
    return {r[0], r[1]};
}

std::size_t ScanVolume::denseBytes() const
{
    return std::size_t(mImpl->image->GetNumberOfPoints()) * std::size_t(mImpl->image->GetScalarSize());
}

const std::string& ScanVolume::source() const { return mImpl->source; }

void ScanVolume::readSlice(int k, float* out) const
{
    const openvdb::Coord d = dims();
    const size_t count = size_t(d.x()) * size_t(d.y());
    const void* src = static_cast<const char*>(mImpl->image->GetScalarPointer()) +
                      size_t(k) * count * size_t(mImpl->image->GetScalarSize());
    switch (mImpl->image->GetScalarType()) {
        vtkTemplateMacro(copyRow<VTK_TT>(src, count, out));
    default: throw InputError(source() + ": unsupported sample type");
    }
}

void ScanVolume::sample(const openvdb::Vec3d* points, std::size_t count, float outside, float* out) const
{
    const void* src = mImpl->image->GetScalarPointer();
    switch (mImpl->image->GetScalarType()) {
        vtkTemplateMacro(sampleTrilinear<VTK_TT>(src, dims(), points, count, outside, out));
    default: throw InputError(source() + ": unsupported sample type");
    }
}

ScanVolume ScanVolume::cropped(const openvdb::CoordBBox& box) const
{
    const openvdb::Coord d = dims();
    openvdb::CoordBBox clipped = box;
    clipped.intersect(openvdb::CoordBBox(openvdb::Coord(0), d.offsetBy(-1)));
    if (clipped.empty()) {
        throw InputError(source() + ": the crop box " + std::to_string(box.min().x()) + "," +
                         std::to_string(box.min().y()) + "," + std::to_string(box.min().z()) + " .. " +
                         std::to_string(box.max().x()) + "," + std::to_string(box.max().y()) + "," +
                         std::to_string(box.max().z()) + " misses the scan (0,0,0 .. " + std::to_string(d.x() - 1) +
                         "," + std::to_string(d.y() - 1) + "," + std::to_string(d.z() - 1) + ")");
    }
    vtkNew<vtkExtractVOI> extract;
    extract->SetInputData(mImpl->image);
    extract->SetVOI(clipped.min().x(), clipped.max().x(), clipped.min().y(), clipped.max().y(), clipped.min().z(),
                    clipped.max().z());
    extract->Update();
    vtkSmartPointer<vtkImageData> image = extract->GetOutput();
    return makeScan(image, mImpl->worldFromIndex, source());
}

ScanVolume ScanVolume::smoothed(double sigmaWorld) const
{
    if (!(sigmaWorld > 0.0) || !std::isfinite(sigmaWorld)) {
        throw InputError("smoothing sigma must be a positive number (got " + formatNumber(sigmaWorld) + ")");
    }
    openvdb::Vec3d sigmaVoxels;
    for (int a = 0; a < 3; ++a) sigmaVoxels[a] = sigmaWorld / spacing(a);
    return gaussian(sigmaVoxels);
}

std::optional<ScanVolume> ScanVolume::antiAliased(double voxelSizeWorld) const
{
    openvdb::Vec3d sigmaVoxels(0.0);
    for (int a = 0; a < 3; ++a) {
        const double s = spacing(a);
        if (dims()[a] > 1 && voxelSizeWorld > s)
            sigmaVoxels[a] = 0.5 * std::sqrt(voxelSizeWorld * voxelSizeWorld - s * s) / s;
    }
    if (sigmaVoxels.x() < kMinSigmaVoxels && sigmaVoxels.y() < kMinSigmaVoxels && sigmaVoxels.z() < kMinSigmaVoxels)
        return std::nullopt;
    return gaussian(sigmaVoxels);
}

double ScanVolume::spacing(int axis) const
{
    const auto& m = mImpl->worldFromIndex;
    return openvdb::Vec3d(m[axis][0], m[axis][1], m[axis][2]).length();  // the length of the placement's row
}

ScanVolume ScanVolume::gaussian(const openvdb::Vec3d& sigmaVoxels) const
{
    vtkNew<vtkImageGaussianSmooth> smooth;
    smooth->SetInputData(mImpl->image);
    smooth->SetDimensionality(3);
    smooth->SetStandardDeviations(sigmaVoxels.x(), sigmaVoxels.y(), sigmaVoxels.z());
    smooth->SetRadiusFactors(3.0, 3.0, 3.0);
    smooth->Update();
    auto impl = std::make_shared<Impl>(*mImpl);
    impl->image = smooth->GetOutput();
    return ScanVolume(impl);
}

double ScanVolume::otsuThreshold() const
{
    const auto [lo, hi] = range();
    if (!(hi > lo))
        throw InputError(source() + ": every sample is " + formatNumber(lo) + ": there is no surface to find");
    constexpr int kBins = 256;
    std::array<double, kBins> histogram{};
    const openvdb::Coord d = dims();
    std::vector<float> slice(size_t(d.x()) * size_t(d.y()));
    for (int k = 0; k < d.z(); ++k) {
        readSlice(k, slice.data());
        for (float v : slice) histogram[size_t(std::clamp(int((v - lo) / (hi - lo) * kBins), 0, kBins - 1))] += 1.0;
    }
    double total = 0.0, sumAll = 0.0;
    for (int i = 0; i < kBins; ++i) {
        total += histogram[size_t(i)];
        sumAll += i * histogram[size_t(i)];
    }
    double weightBelow = 0.0, sumBelow = 0.0, best = -1.0;
    int bestBin = 0;
    for (int i = 0; i < kBins - 1; ++i) {  // class "below" is bins 0..i
        weightBelow += histogram[size_t(i)];
        sumBelow += i * histogram[size_t(i)];
        const double weightAbove = total - weightBelow;
        if (weightBelow == 0.0 || weightAbove == 0.0) continue;
        const double meanBelow = sumBelow / weightBelow, meanAbove = (sumAll - sumBelow) / weightAbove;
        const double between = weightBelow * weightAbove * (meanBelow - meanAbove) * (meanBelow - meanAbove);
        if (between > best) {
            best = between;
            bestBin = i;
        }
    }
    return lo + (hi - lo) * (bestBin + 1) / kBins;  // the upper edge of the lower class
}

bool isScanPath(const fs::path& path)
{
    static const std::array<const char*, 6> known{".nii", ".nii.gz", ".nrrd", ".nhdr", ".mha", ".mhd"};
    const std::string ext = lowerExtension(path);
    return fs::is_directory(path) || std::find(known.begin(), known.end(), ext) != known.end();
}

ScanVolume readScan(const fs::path& path)
{
    if (!fs::exists(path)) throw InputError(path.string() + ": no such file or directory");
    if (fs::is_directory(path)) return readDicomSeries(path);
    const std::string ext = lowerExtension(path);
    if (ext == ".nii" || ext == ".nii.gz") return readNifti(path);
    if (ext == ".nrrd" || ext == ".nhdr") return readWithDirection<vtkNrrdReader>(path);
    if (ext == ".mha" || ext == ".mhd") return readWithDirection<vtkMetaImageReader>(path);
    throw InputError(path.string() + ": unknown scan format '" + ext +
                         "' (expected .nii, .nii.gz, .nrrd, .nhdr, .mha, .mhd, a DICOM directory, or raw samples "
                         "with their dimensions given)",
                     Remedy::DescribeRawLayout);
}

ScanVolume readRawScan(const fs::path& path, const RawLayout& layout)
{
    const int type = vtkTypeOf(layout.type);
    if (layout.dims.x() < 1 || layout.dims.y() < 1 || layout.dims.z() < 1) {
        throw InputError(path.string() + ": raw dimensions must be positive");
    }
    for (int a = 0; a < 3; ++a) {
        if (!(layout.spacing[a] > 0.0) || !std::isfinite(layout.spacing[a]))
            throw InputError("raw spacing must be positive");
    }
    if (!fs::is_regular_file(path)) throw InputError(path.string() + ": no such file");
    const double needed = double(layout.headerBytes) + double(layout.dims.x()) * layout.dims.y() * layout.dims.z() *
                                                           vtkDataArray::GetDataTypeSize(type);
    if (double(fs::file_size(path)) < needed) {
        throw InputError(path.string() + ": " + std::to_string(fs::file_size(path)) + " bytes, but the layout needs " +
                         formatNumber(needed) + " (truncated, or wrong dimensions or type?)");
    }
    vtkNew<vtkImageReader2> reader;
    reader->SetFileName(path.string().c_str());
    reader->SetFileDimensionality(3);
    reader->SetDataExtent(0, layout.dims.x() - 1, 0, layout.dims.y() - 1, 0, layout.dims.z() - 1);
    reader->SetDataScalarType(type);
    reader->SetNumberOfScalarComponents(1);
    reader->SetHeaderSize(layout.headerBytes);
    if (layout.bigEndian) reader->SetDataByteOrderToBigEndian();
    else reader->SetDataByteOrderToLittleEndian();
    reader->SetDataSpacing(layout.spacing[0], layout.spacing[1], layout.spacing[2]);
    reader->SetDataOrigin(layout.origin[0], layout.origin[1], layout.origin[2]);
    reader->FileLowerLeftOn();
    vtkSmartPointer<vtkImageData> image = runReader(reader, path.string());
    return makeScan(image, placement(image, nullptr), path.string());
}

}  // namespace sculpt
