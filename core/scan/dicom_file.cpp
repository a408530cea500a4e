// SPDX-License-Identifier: Apache-2.0
#include "core/scan/dicom_file.h"

#include "core/base/errors.h"
#include "core/base/isolated_call.h"
#include "core/base/memory_budget.h"

#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkType.h>

#include <cmath>
#include <cstdlib>
#include <gdcmImageReader.h>
#include <gdcmReader.h>
#include <gdcmSequenceOfFragments.h>
#include <gdcmSequenceOfItems.h>
#include <gdcmTrace.h>
#include <optional>
#include <sstream>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

const gdcm::Tag kPixelSpacing(0x0028, 0x0030);
const gdcm::Tag kPixelData(0x7FE0, 0x0010);
const gdcm::Tag kPosition(0x0020, 0x0032);
const gdcm::Tag kOrientation(0x0020, 0x0037);
const gdcm::Tag kSeriesUid(0x0020, 0x000E);
// Enhanced multi-frame files keep the geometry in functional groups: shared by all frames, or
// one item per frame, each holding a sequence per aspect.
const gdcm::Tag kSharedGroups(0x5200, 0x9229);
const gdcm::Tag kPerFrameGroups(0x5200, 0x9230);
const gdcm::Tag kPixelMeasures(0x0028, 0x9110);
const gdcm::Tag kPlanePosition(0x0020, 0x9113);
const gdcm::Tag kPlaneOrientation(0x0020, 0x9116);

/// The element's text, if it is there and holds bytes.
std::optional<std::string> text(const gdcm::DataSet& ds, const gdcm::Tag& tag)
{
    if (!ds.FindDataElement(tag)) return std::nullopt;
    const gdcm::ByteValue* value = ds.GetDataElement(tag).GetByteValue();
    if (!value || !value->GetPointer()) return std::nullopt;
    return std::string(value->GetPointer(), value->GetLength());
}

/// A decimal string's values (DS: numbers separated by backslashes); empty if absent or if any
/// value is not a finite number.
std::vector<double> decimals(const gdcm::DataSet& ds, const gdcm::Tag& tag)
{
    const std::optional<std::string> value = text(ds, tag);
    if (!value) return {};
    std::vector<double> numbers;
    std::istringstream in(*value);
    for (std::string item; std::getline(in, item, '\\');) {
        const char* begin = item.c_str();
        char* end = nullptr;
        const double number = std::strtod(begin, &end);
        if (end == begin || !std::isfinite(number)) return {};
        numbers.push_back(number);
    }
    return numbers;
}

/// The first item's data set of a sequence element, or of item `index` (0-based).
const gdcm::DataSet* item(const gdcm::DataSet& ds, const gdcm::Tag& sequence, std::size_t index = 0)
{
    if (!ds.FindDataElement(sequence)) return nullptr;
    const gdcm::SmartPointer<gdcm::SequenceOfItems> items = ds.GetDataElement(sequence).GetValueAsSQ();
    if (!items || index >= items->GetNumberOfItems()) return nullptr;
    return &items->GetItem(index + 1).GetNestedDataSet();  // GDCM counts items from 1
}

/// Where an enhanced file keeps `tag` for `frame`: its own functional group, else the shared one.
std::vector<double> groupDecimals(const gdcm::DataSet& ds, std::size_t frame, const gdcm::Tag& group,
                                  const gdcm::Tag& tag)
{
    for (const gdcm::DataSet* groups : {item(ds, kPerFrameGroups, frame), item(ds, kSharedGroups)}) {
        if (const gdcm::DataSet* aspect = groups ? item(*groups, group) : nullptr) {
            std::vector<double> values = decimals(*aspect, tag);
            if (!values.empty()) return values;
        }
    }
    return {};
}

/// A classic file's value, else the enhanced file's for `frame`; `count` numbers or nothing.
std::vector<double> geometry(const gdcm::DataSet& ds, std::size_t frame, const gdcm::Tag& group, const gdcm::Tag& tag,
                             std::size_t count)
{
    std::vector<double> values = decimals(ds, tag);
    if (values.size() != count) values = groupDecimals(ds, frame, group, tag);
    if (values.size() != count) values.clear();
    return values;
}

int vtkTypeOf(const gdcm::PixelFormat& format, const std::string& file)
{
    if (format.GetSamplesPerPixel() != 1)
        throw InputError(file + ": a colour image (" + std::to_string(format.GetSamplesPerPixel()) +
                         " samples per pixel); a scan has one");
    switch (format.GetScalarType()) {
    case gdcm::PixelFormat::UINT8: return VTK_UNSIGNED_CHAR;
    case gdcm::PixelFormat::INT8: return VTK_SIGNED_CHAR;
    case gdcm::PixelFormat::UINT12:
    case gdcm::PixelFormat::UINT16: return VTK_UNSIGNED_SHORT;
    case gdcm::PixelFormat::INT12:
    case gdcm::PixelFormat::INT16: return VTK_SHORT;
    case gdcm::PixelFormat::UINT32: return VTK_UNSIGNED_INT;
    case gdcm::PixelFormat::INT32: return VTK_INT;
    case gdcm::PixelFormat::FLOAT32: return VTK_FLOAT;
    case gdcm::PixelFormat::FLOAT64: return VTK_DOUBLE;
    default: throw InputError(file + ": pixel format " + format.GetScalarTypeAsString() + " is not supported");
    }
}

/// GDCM reads a Pixel Data element that the end of its file cuts short as if whole (its
/// "use file at own risk" warning; its JPEG lossless codec decodes a cut fragment too), the
/// missing bytes garbage: the element, with its fragments and their delimiter, must end in the
/// file. Read again up to it with it skipped, the stream stands where its value begins.
void requirePixelDataInFile(const gdcm::Image& image, const fs::path& path)
{
    const gdcm::DataElement& pixels = image.GetDataElement();
    std::uint64_t bytes = 0;
    if (const gdcm::ByteValue* value = pixels.GetByteValue()) bytes = value->GetLength();
    else if (const gdcm::SequenceOfFragments* fragments = pixels.GetSequenceOfFragments())
        bytes = fragments->ComputeLength();
    gdcm::Reader upToPixels;
    upToPixels.SetFileName(path.string().c_str());
    if (!upToPixels.ReadUpToTag(kPixelData, {kPixelData}))
        throw InputError(path.string() + ": not a DICOM image (GDCM cannot read it)");
    const std::uint64_t end = upToPixels.GetStreamCurrentPosition() + bytes;
    const std::uint64_t size = fs::file_size(path);
    if (end > size) {
        throw InputError(path.string() + ": the pixel data claims " + std::to_string(bytes) + " bytes, " +
                         std::to_string(end - size) + " more than the file holds (truncated?)");
    }
}

/// The decoded pixels of every frame, in the stored type.
vtkSmartPointer<vtkImageData> decodePixels(const gdcm::Image& image, const std::string& file)
{
    const int type = vtkTypeOf(image.GetPixelFormat(), file);
    const unsigned columns = image.GetDimension(0), rows = image.GetDimension(1);
    const unsigned frames = image.GetNumberOfDimensions() == 3 ? image.GetDimension(2) : 1;
    if (columns == 0 || rows == 0 || frames == 0) throw InputError(file + ": the image has no pixels");
    const double bytes = double(columns) * rows * frames * vtkDataArray::GetDataTypeSize(type);
    // Decoded straight into the samples; GDCM's decoders may hold a frame buffer of their own.
    requireMemory(2.0 * bytes, file + " (" + std::to_string(columns) + " x " + std::to_string(rows) + " x " +
                                   std::to_string(frames) + " pixels)");
    if (double(image.GetBufferLength()) != bytes) {
        throw InputError(file + ": the pixel data holds " + std::to_string(image.GetBufferLength()) +
                         " bytes, the image needs " + std::to_string(std::size_t(bytes)));
    }
    auto samples = vtkSmartPointer<vtkImageData>::New();
    samples->SetDimensions(int(columns), int(rows), int(frames));
    samples->AllocateScalars(type, 1);
    if (!image.GetBuffer(static_cast<char*>(samples->GetScalarPointer()))) {
        throw InputError(
            file + ": the pixel data cannot be decoded (transfer syntax " +
            std::string(image.GetTransferSyntax().GetString() ? image.GetTransferSyntax().GetString() : "unknown") +
            ", truncated or corrupt?)");
    }
    return samples;
}

/// Stored values to modality units (Hounsfield units for CT): value = slope * stored + intercept.
void rescale(vtkImageData* samples, double slope, double intercept)
{
    if (slope == 1.0 && intercept == 0.0) return;
    vtkDataArray* stored = samples->GetPointData()->GetScalars();
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfValues(stored->GetNumberOfTuples());
    for (vtkIdType i = 0; i < stored->GetNumberOfTuples(); ++i)
        values->SetValue(i, float(slope * stored->GetTuple1(i) + intercept));
    samples->GetPointData()->SetScalars(values);
}

openvdb::Vec3d vec3(const std::vector<double>& v, std::size_t at) { return {v[at], v[at + 1], v[at + 2]}; }

/// Each frame's position: its own (classic files have one frame), else stepped from the first
/// along the slice normal by the spacing between slices GDCM found.
std::vector<openvdb::Vec3d> framePositions(const gdcm::DataSet& ds, const gdcm::Image& image, std::size_t frames,
                                           const openvdb::Vec3d& normal, const std::string& file)
{
    std::vector<openvdb::Vec3d> positions;
    for (std::size_t f = 0; f < frames; ++f) {
        const std::vector<double> p = geometry(ds, f, kPlanePosition, kPosition, 3);
        if (p.empty() && f == 0) throw InputError(file + ": no image position (0020,0032): not an image slice");
        positions.push_back(p.empty() ? positions.front() + normal * (image.GetSpacing(2) * double(f)) : vec3(p, 0));
    }
    return positions;
}

/// Once: GDCM's own messages off, as every failure reaches us as a return value we report.
void quietGdcm()
{
    static const bool quiet = [] {
        gdcm::Trace::SetWarning(false);
        gdcm::Trace::SetError(false);
        gdcm::Trace::SetDebug(false);
        return true;
    }();
    (void)quiet;
}

}  // namespace

DicomFrames readDicomFile(const fs::path& path)
{
    quietGdcm();
    const std::string file = path.string();
    noteIsolatedSubject(file);  // GDCM may abort on a damaged file: name it
    gdcm::ImageReader reader;
    reader.SetFileName(file.c_str());
    if (!reader.Read()) throw InputError(file + ": not a DICOM image (GDCM cannot read it)");
    const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
    const gdcm::Image& image = reader.GetImage();
    DicomFrames frames;
    frames.file = file;
    const std::vector<double> o = geometry(ds, 0, kPlaneOrientation, kOrientation, 6);
    if (o.empty()) throw InputError(file + ": no image orientation (0020,0037): not an image slice");
    frames.rowDirection = vec3(o, 0);
    frames.columnDirection = vec3(o, 3);
    if (std::abs(frames.rowDirection.length() - 1.0) > 0.01 || std::abs(frames.columnDirection.length() - 1.0) > 0.01 ||
        std::abs(frames.rowDirection.dot(frames.columnDirection)) > 0.01) {
        throw InputError(file + ": the image orientation (0020,0037) is not two perpendicular unit directions");
    }
    frames.rowDirection.normalize();
    frames.columnDirection.normalize();
    const std::vector<double> spacing = geometry(ds, 0, kPixelMeasures, kPixelSpacing, 2);
    if (!spacing.empty()) {
        frames.rowSpacing = spacing[0];  // DICOM gives the spacing between rows first
        frames.columnSpacing = spacing[1];
    }
    if (!(frames.rowSpacing > 0.0) || !(frames.columnSpacing > 0.0))
        throw InputError(file + ": the pixel spacing (0028,0030) is not positive");
    requirePixelDataInFile(image, path);
    frames.samples = decodePixels(image, file);
    rescale(frames.samples, image.GetSlope(), image.GetIntercept());
    const openvdb::Vec3d normal = frames.rowDirection.cross(frames.columnDirection);
    frames.positions =
        framePositions(ds, image, std::size_t(frames.samples->GetDimensions()[2]), normal.unitSafe(), file);
    if (const std::optional<std::string> uid = text(ds, kSeriesUid)) {
        frames.seriesUid = uid->substr(0, uid->find_last_not_of(std::string(" \0", 2)) + 1);
    }
    return frames;
}

}  // namespace sculpt
