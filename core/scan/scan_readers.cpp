// SPDX-License-Identifier: Apache-2.0
#include "core/scan/scan_readers.h"

#include "core/base/enum_names.h"
#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/base/isolated_call.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/scan/dicom_directory.h"
#include "core/scan/dicom_series.h"
#include "core/scan/header_checks.h"
#include "core/scan/header_text.h"
#include "core/scan/inrimage_file.h"
#include "core/scan/kept_scan.h"
#include "core/scan/scan_frame.h"
#include "core/scan/scan_transfer.h"
#include "core/scan/vtk_image_scan.h"

#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkMatrix3x3.h>
#include <vtkMetaImageReader.h>
#include <vtkNIFTIImageHeader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkNrrdReader.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>
#include <vtkType.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// The file's slice order back: VTK reverses the slices of a NIfTI whose qfac is -1 (and its
/// matrices with them), and a segmentation written for the scan must index the file's samples.
/// The placement is turned to match, so every sample stays where it was.
openvdb::Mat4d inFileSliceOrder(vtkImageData* image, const openvdb::Mat4d& worldFromIndex)
{
    int d[3];
    image->GetDimensions(d);
    const std::size_t slice = std::size_t(d[0]) * std::size_t(d[1]) * std::size_t(image->GetScalarSize());
    auto* bytes = static_cast<unsigned char*>(image->GetScalarPointer());
    for (int k = 0; k < d[2] / 2; ++k)
        std::swap_ranges(bytes + std::size_t(k) * slice, bytes + std::size_t(k + 1) * slice,
                         bytes + std::size_t(d[2] - 1 - k) * slice);
    openvdb::Mat4d m = worldFromIndex;  // row vectors: row 2 is the k step, row 3 the origin
    for (int c = 0; c < 3; ++c) {
        m[3][c] += double(d[2] - 1) * m[2][c];
        m[2][c] = -m[2][c];
    }
    image->Modified();
    return m;
}

ScanVolume readNifti(const fs::path& path)
{
    vtkNew<vtkNIFTIImageReader> reader;
    reader->SetFileName(path.string().c_str());
    // FSL's atlases (JHU, jhu189 in mricron-data) store a left-handed sform beside a qform: VTK
    // says so and reads them right, placed by the sform (vtkNIFTIImageReader::GetSFormMatrix).
    std::vector<std::string> notes;
    vtkSmartPointer<vtkImageData> image =
        runReader(reader, path.string(), {"SFormMatrix is flipped compared to QFormMatrix"}, &notes);
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
    std::vector<std::string> warnings;
    if (!notes.empty())
        warnings.push_back(path.string() + ": its sform is mirrored against its qform; placed by the sform");
    if (!orientation)
        warnings.push_back(path.string() + ": neither sform nor qform places it: placed by its spacings, as RAS");
    // The sform and qform map to RAS (x to the right, y to the front), in xyzt_units.
    const int units = reader->GetNIFTIHeader()->GetXYZTUnits();
    openvdb::Mat4d worldFromIndex =
        inLpsMillimetres(placement(image, orientation), kRasSigns, niftiMillimetresPer(units));
    if (reader->GetQFac() < 0.0) worldFromIndex = inFileSliceOrder(image, worldFromIndex);
    return makeScan(image, worldFromIndex, path.string(), warnings);
}

/// A NRRD or MetaImage: VTK reads the samples, the header's own placement (`place`) puts them
/// where the file says (VTK 9.1's readers drop the direction cosines).
template <typename ReaderT>
ScanVolume readPlaced(const fs::path& path, ScanPlacement (*place)(const fs::path&))
{
    vtkNew<ReaderT> reader;
    reader->SetFileName(path.string().c_str());
    vtkSmartPointer<vtkImageData> image = runReader(reader, path.string());
    ScanPlacement placed = place(path);
    return makeScan(image, placed.worldFromIndex, path.string(), std::move(placed.notes));
}

constexpr EnumNames<int, 8> kSampleTypes{{{VTK_UNSIGNED_CHAR, "uint8"},
                                          {VTK_SIGNED_CHAR, "int8"},
                                          {VTK_UNSIGNED_SHORT, "uint16"},
                                          {VTK_SHORT, "int16"},
                                          {VTK_UNSIGNED_INT, "uint32"},
                                          {VTK_INT, "int32"},
                                          {VTK_FLOAT, "float32"},
                                          {VTK_DOUBLE, "float64"}}};

/// VTK's scalar type for a raw layout's sample type name.
int vtkTypeOf(const std::string& type) { return enumFromName(kSampleTypes, type, "sample type"); }

enum class ScanFormat { Dicom, Nifti, Nrrd, MetaImage, Inrimage };

ScanFormat formatOf(const fs::path& path)
{
    if (fs::is_directory(path) || isDicomFile(path) || hasDicomMarker(path)) return ScanFormat::Dicom;
    const std::string ext = lowerExtension(path);
    if (ext == ".nii" || ext == ".nii.gz") return ScanFormat::Nifti;
    if (ext == ".nrrd" || ext == ".nhdr") return ScanFormat::Nrrd;
    if (ext == ".mha" || ext == ".mhd") return ScanFormat::MetaImage;
    if (ext == ".inr" || ext == ".inr.gz") return ScanFormat::Inrimage;
    throw InputError(path.string() + ": unknown scan format '" + ext +
                         "' (expected .nii, .nii.gz, .nrrd, .nhdr, .mha, .mhd, .inr, .inr.gz, a DICOM file or a DICOM "
                         "directory, or a .vdb document keeping its scan); raw samples "
                         "need their layout given",
                     Remedy::DescribeRawLayout);
}

/// Our checks of the header against the file, in this process: they are bounded, and so a
/// fuzzer sees their coverage.
void checkHeader(const fs::path& path, ScanFormat format)
{
    switch (format) {
    case ScanFormat::Dicom: return;  // GDCM parses DICOM; the child process contains it
    case ScanFormat::Nifti: return checkNiftiHeader(path);
    case ScanFormat::Nrrd: return checkNrrdHeader(path);
    case ScanFormat::MetaImage: return checkMetaImageHeader(path);
    case ScanFormat::Inrimage: return checkInrimageHeader(path);
    }
}

/// What readScan does in the isolated child: the third-party reader.
ScanVolume decodeScan(const fs::path& path, ScanFormat format)
{
    switch (format) {
    case ScanFormat::Dicom: return readDicomSeries(path);
    case ScanFormat::Nifti: return readNifti(path);
    case ScanFormat::Nrrd: return readPlaced<vtkNrrdReader>(path, nrrdPlacement);
    case ScanFormat::MetaImage: return readPlaced<vtkMetaImageReader>(path, metaImagePlacement);
    case ScanFormat::Inrimage: return readInrimage(path);
    }
    throw std::logic_error("unknown scan format");
}

/// The library that decodes the format, for messages.
std::string readerOf(ScanFormat format)
{
    switch (format) {
    case ScanFormat::Dicom: return "the DICOM reader";
    case ScanFormat::Nifti: return "the NIfTI reader";
    case ScanFormat::Nrrd: return "the NRRD reader";
    case ScanFormat::MetaImage: return "the MetaImage reader";
    case ScanFormat::Inrimage: return "the INRIMAGE reader";
    }
    return "the scan reader";
}

/// Processor time a scan's decoding may take: a 1000-slice JPEG 2000 CT decodes in about 30 s.
constexpr int kScanReadCpuSeconds = 300;

/// How many times its bytes a DICOM series may need to decode, and room for the libraries. RLE
/// and the JPEG codecs expand far less than 64 times; GDCM allocates whatever an element's
/// length claims, so a length past the end of its file fails at once within this bound instead
/// of taking the machine's memory.
constexpr std::uint64_t kDicomExpansion = 64;
constexpr std::uint64_t kDicomLibraryBytes = std::uint64_t(1) << 30;

/// The bytes of the files a DICOM path may read: its directory's (with the folders a DICOMDIR
/// names) when it is a slice, since the rest of its series is read too.
std::uint64_t dicomInputBytes(const fs::path& path)
{
    if (!fs::is_directory(path)) return dicomInputBytes(path.parent_path().empty() ? "." : path.parent_path());
    std::uint64_t bytes = 0;
    std::error_code error;
    for (fs::recursive_directory_iterator it(path, error), end; !error && it != end; it.increment(error)) {
        if (it->is_regular_file(error)) bytes += it->file_size(error);
    }
    return bytes;
}

/// What decoding `path` may allocate: a DICOM series no more than its files can hold; the other
/// formats' headers have been checked against their files (header_checks.h) before this.
std::uint64_t decodeBudget(const fs::path& path, ScanFormat format)
{
    if (format != ScanFormat::Dicom) return availableMemoryBytes();
    return std::min(availableMemoryBytes(), kDicomLibraryBytes + kDicomExpansion * dicomInputBytes(path));
}

/// Runs `decode` in a child process (isolated_call.h) under `memoryBytes` and brings its scan back.
template <typename Decode>
ScanVolume readIsolated(const fs::path& path, const std::string& reader, std::uint64_t memoryBytes,
                        const Decode& decode)
{
    IsolationLimits limits;
    limits.subject = path.string();
    limits.reader = reader;
    limits.memoryBytes = memoryBytes;
    limits.cpuSeconds = kScanReadCpuSeconds;
    return unpackScan(runIsolated(limits, [&] {
        vtkSMPTools::SetBackend("Sequential");  // the parent's TBB workers do not exist in the child
        return packScan(decode());
    }));
}

ScanVolume decodeRawScan(const fs::path& path, const RawLayout& layout)
{
    const int type = vtkTypeOf(layout.type);
    if (layout.dims.x() < 1 || layout.dims.y() < 1 || layout.dims.z() < 1) {
        throw InputError(path.string() + ": raw dimensions must be positive");
    }
    requireSpacings({layout.spacing[0], layout.spacing[1], layout.spacing[2]}, path.string() + ": ", "the raw spacing");
    for (int a = 0; a < 3; ++a) {
        if (!(layout.spacing[a] > 0.0)) throw InputError(path.string() + ": the raw spacing must be positive");
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
    return makeScan(image, placement(image, nullptr), path.string(),
                    {path.string() + ": raw samples declare no patient frame: placed as given, as LPS millimetres"});
}

}  // namespace

bool isScanPath(const fs::path& path)
{
    static const std::array<const char*, 8> known{".nii", ".nii.gz", ".nrrd", ".nhdr",
                                                  ".mha", ".mhd",    ".inr",  ".inr.gz"};
    const std::string ext = lowerExtension(path);
    return fs::is_directory(path) || isDicomFile(path) || std::find(known.begin(), known.end(), ext) != known.end() ||
           hasDicomMarker(path);
}

ScanVolume readScan(const fs::path& path)
{
    if (!fs::exists(path)) throw InputError(path.string() + ": no such file or directory");
    if (lowerExtension(path) == ".vdb") return readKeptScan(path);  // our own reader, in this process
    const ScanFormat format = formatOf(path);
    checkHeader(path, format);
    return readIsolated(path, readerOf(format), decodeBudget(path, format), [&] { return decodeScan(path, format); });
}

ScanVolume readRawScan(const fs::path& path, const RawLayout& layout)
{
    return readIsolated(path, "the raw sample reader", availableMemoryBytes(),
                        [&] { return decodeRawScan(path, layout); });
}

}  // namespace sculpt
