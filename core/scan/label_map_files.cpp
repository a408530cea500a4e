// SPDX-License-Identifier: Apache-2.0
#include "core/scan/label_map_files.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/file_extension.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <zlib.h>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

enum class LabelFormat { Nifti, NiftiGz, Nrrd, SlicerSegmentation };

std::optional<LabelFormat> formatOf(const fs::path& path)
{
    const std::string name = path.filename().string(), ext = lowerExtension(path);
    const auto endsWith = [&](const std::string& tail) {
        return name.size() > tail.size() && std::equal(tail.rbegin(), tail.rend(), name.rbegin(), [](char a, char b) {
                   return a == std::tolower(static_cast<unsigned char>(b));
               });
    };
    if (endsWith(".seg.nrrd")) return LabelFormat::SlicerSegmentation;
    if (ext == ".nrrd") return LabelFormat::Nrrd;
    if (ext == ".nii") return LabelFormat::Nifti;
    if (ext == ".nii.gz") return LabelFormat::NiftiGz;
    return std::nullopt;
}

/// The samples in their file type, little-endian: bytes when every label fits in one.
std::string sampleBytes(const LabelMap& map)
{
    const bool bytes = map.largestLabel() <= 255;
    std::string out(map.labels.size() * (bytes ? 1 : 2), '\0');
    for (std::size_t n = 0; n < map.labels.size(); ++n) {
        const std::uint16_t v = map.labels[n];
        if (bytes) {
            out[n] = char(v);
        } else {
            out[2 * n] = char(v & 0xff);
            out[2 * n + 1] = char(v >> 8);
        }
    }
    return out;
}

/// `bytes` as a gzip stream (what .nii.gz and NRRD's gzip encoding hold).
std::string gzipped(const std::string& bytes)
{
    z_stream zs{};
    if (deflateInit2(&zs, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw InputError("cannot start compressing the label map");
    std::string out(deflateBound(&zs, uLong(bytes.size())), '\0');
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    zs.avail_in = uInt(bytes.size());
    zs.next_out = reinterpret_cast<Bytef*>(out.data());
    zs.avail_out = uInt(out.size());
    const int result = deflate(&zs, Z_FINISH);
    out.resize(zs.total_out);
    deflateEnd(&zs);
    if (result != Z_STREAM_END) throw InputError("cannot compress the label map");
    return out;
}

/// The lattice as RAS rows for column vectors: ras = A (i, j, k, 1). LPS to RAS negates x and y.
std::array<std::array<double, 4>, 3> rasAffine(const ScanLattice& lattice)
{
    const openvdb::Mat4d& m = lattice.worldFromIndex;  // row vectors: world = (i, j, k, 1) m
    std::array<std::array<double, 4>, 3> a{};
    for (int c = 0; c < 3; ++c) {
        const double sign = c < 2 ? -1.0 : 1.0;
        for (int r = 0; r < 4; ++r) a[std::size_t(c)][std::size_t(r)] = sign * m[r][c];
    }
    return a;
}

/// NIfTI's quaternion of the rotation in `a` (its columns normalised), with qfac -1 for a
/// mirrored lattice (nifti1.h, method 2).
struct Quatern {
    double b = 0.0, c = 0.0, d = 0.0, qfac = 1.0;
};
Quatern quaternOf(const std::array<std::array<double, 4>, 3>& a)
{
    double r[3][3];
    for (int col = 0; col < 3; ++col) {
        const double length = std::sqrt(a[0][col] * a[0][col] + a[1][col] * a[1][col] + a[2][col] * a[2][col]);
        for (int row = 0; row < 3; ++row) r[row][col] = a[std::size_t(row)][std::size_t(col)] / length;
    }
    const double det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                       r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                       r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
    Quatern q;
    if (det < 0.0) {
        q.qfac = -1.0;
        for (auto& row : r) row[2] = -row[2];
    }
    double qa = r[0][0] + r[1][1] + r[2][2] + 1.0;
    if (qa > 0.5) {
        qa = 0.5 * std::sqrt(qa);
        q.b = 0.25 * (r[2][1] - r[1][2]) / qa;
        q.c = 0.25 * (r[0][2] - r[2][0]) / qa;
        q.d = 0.25 * (r[1][0] - r[0][1]) / qa;
    } else if (const double xd = 1.0 + r[0][0] - r[1][1] - r[2][2]; xd > 1.0) {
        q.b = 0.5 * std::sqrt(xd);
        q.c = 0.25 * (r[0][1] + r[1][0]) / q.b;
        q.d = 0.25 * (r[0][2] + r[2][0]) / q.b;
        qa = 0.25 * (r[2][1] - r[1][2]) / q.b;
    } else if (const double yd = 1.0 + r[1][1] - r[0][0] - r[2][2]; yd > 1.0) {
        q.c = 0.5 * std::sqrt(yd);
        q.b = 0.25 * (r[0][1] + r[1][0]) / q.c;
        q.d = 0.25 * (r[1][2] + r[2][1]) / q.c;
        qa = 0.25 * (r[0][2] - r[2][0]) / q.c;
    } else {
        q.d = 0.5 * std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]);
        q.b = 0.25 * (r[0][2] + r[2][0]) / q.d;
        q.c = 0.25 * (r[1][2] + r[2][1]) / q.d;
        qa = 0.25 * (r[1][0] - r[0][1]) / q.d;
    }
    if (qa < 0.0) q.b = -q.b, q.c = -q.c, q.d = -q.d;
    return q;
}

template <typename T>
void put(std::string& bytes, std::size_t at, T value)
{
    std::memcpy(bytes.data() + at, &value, sizeof value);
}

/// A NIfTI-1 header (348 bytes) and the 4 bytes of "no extension" before the samples.
std::string niftiHeader(const LabelMap& map)
{
    constexpr std::int16_t kUint8 = 2, kUint16 = 512, kScannerAnat = 1, kIntentLabel = 1002;
    constexpr char kMillimetres = 2;
    const bool bytes = map.largestLabel() <= 255;
    std::string h(352, '\0');
    put(h, 0, std::int32_t(348));
    const openvdb::Coord& d = map.lattice.dims;
    const std::int16_t dim[8] = {3, std::int16_t(d.x()), std::int16_t(d.y()), std::int16_t(d.z()), 1, 1, 1, 1};
    std::memcpy(h.data() + 40, dim, sizeof dim);
    put(h, 68, kIntentLabel);
    put(h, 70, bytes ? kUint8 : kUint16);
    put(h, 72, std::int16_t(bytes ? 8 : 16));
    const auto a = rasAffine(map.lattice);
    const Quatern q = quaternOf(a);
    float pixdim[8] = {float(q.qfac)};
    for (int c = 0; c < 3; ++c)
        pixdim[c + 1] =
            float(std::sqrt(a[0][std::size_t(c)] * a[0][std::size_t(c)] + a[1][std::size_t(c)] * a[1][std::size_t(c)] +
                            a[2][std::size_t(c)] * a[2][std::size_t(c)]));
    std::memcpy(h.data() + 76, pixdim, sizeof pixdim);
    put(h, 108, 352.0f);  // vox_offset
    put(h, 112, 1.0f);    // scl_slope: the samples are the labels
    h[123] = kMillimetres;
    put(h, 128, 0.0f);  // cal_min
    put(h, 124, float(map.largestLabel()));
    std::strncpy(h.data() + 148, "label map: sculpt export-labels", 79);
    put(h, 252, kScannerAnat);  // qform_code
    put(h, 254, kScannerAnat);  // sform_code
    const float quatern[6] = {float(q.b), float(q.c), float(q.d), float(a[0][3]), float(a[1][3]), float(a[2][3])};
    std::memcpy(h.data() + 256, quatern, sizeof quatern);
    for (std::size_t row = 0; row < 3; ++row)
        for (std::size_t col = 0; col < 4; ++col) put(h, 280 + 16 * row + 4 * col, float(a[row][col]));
    std::memcpy(h.data() + 344, "n+1", 4);
    return h;
}

/// A number as NRRD fields hold it: every digit a double needs to come back the same.
std::string exact(double value)
{
    std::ostringstream text;
    text << std::setprecision(17) << value;
    return text.str();
}

/// A segment's fields as 3D Slicer writes and reads them (vtkMRMLSegmentationStorageNode).
void writeSegmentFields(std::ostream& out, const LabelMap& map)
{
    for (std::size_t s = 0; s < map.segments.size(); ++s) {
        const LabelSegment& segment = map.segments[s];
        const std::string key = "Segment" + std::to_string(s) + "_";
        const openvdb::CoordBBox& e = segment.extent;
        out << key << "Color:=" << segment.colour[0] << " " << segment.colour[1] << " " << segment.colour[2] << "\n"
            << key << "ColorAutoGenerated:=0\n";
        if (segment.samples > 0) {
            out << key << "Extent:=" << e.min().x() << " " << e.max().x() << " " << e.min().y() << " " << e.max().y()
                << " " << e.min().z() << " " << e.max().z() << "\n";
        } else {
            out << key << "Extent:=0 -1 0 -1 0 -1\n";
        }
        out << key << "ID:=Segment_" << segment.label << "\n"
            << key << "LabelValue:=" << segment.label << "\n"
            << key << "Layer:=0\n"
            << key << "Name:=" << segment.name << "\n"
            << key << "NameAutoGenerated:=0\n"
            << key << "Tags:=Segmentation.Status:inprogress|\n";
    }
    out << "Segmentation_ContainedRepresentationNames:=Binary labelmap|\n"
        << "Segmentation_MasterRepresentation:=Binary labelmap\n"
        << "Segmentation_ReferenceImageExtentOffset:=0 0 0\n";
}

std::string nrrdHeader(const LabelMap& map, bool segments)
{
    const openvdb::Mat4d& m = map.lattice.worldFromIndex;
    const openvdb::Coord& d = map.lattice.dims;
    std::ostringstream out;
    out << "NRRD0004\n# a label map written by sculpt export-labels\n"
        << "type: " << (map.largestLabel() <= 255 ? "unsigned char" : "unsigned short") << "\ndimension: 3\n"
        << "space: left-posterior-superior\nsizes: " << d.x() << " " << d.y() << " " << d.z() << "\nspace directions:";
    for (int r = 0; r < 3; ++r) out << " (" << exact(m[r][0]) << "," << exact(m[r][1]) << "," << exact(m[r][2]) << ")";
    out << "\nkinds: domain domain domain\nendian: little\nencoding: gzip\nspace origin: (" << exact(m[3][0]) << ","
        << exact(m[3][1]) << "," << exact(m[3][2]) << ")\n";
    if (segments) writeSegmentFields(out, map);
    out << "\n";
    return out.str();
}

}  // namespace

void checkLabelMapPath(const fs::path& path)
{
    if (!formatOf(path)) {
        throw InputError(path.string() + ": a label map is written as .nii, .nii.gz, .nrrd or .seg.nrrd, not '" +
                         lowerExtension(path) + "'");
    }
}

void writeLabelMap(const LabelMap& map, const fs::path& path)
{
    checkLabelMapPath(path);
    const std::optional<LabelFormat> format = formatOf(path);
    const openvdb::Coord& d = map.lattice.dims;
    if ((*format == LabelFormat::Nifti || *format == LabelFormat::NiftiGz) &&
        std::max({d.x(), d.y(), d.z()}) > std::numeric_limits<std::int16_t>::max()) {
        throw InputError(path.string() + ": NIfTI-1 holds at most 32767 samples along an axis; write a .nrrd");
    }
    switch (*format) {
    case LabelFormat::Nifti: return writeFileAtomically(path, niftiHeader(map) + sampleBytes(map));
    case LabelFormat::NiftiGz: return writeFileAtomically(path, gzipped(niftiHeader(map) + sampleBytes(map)));
    case LabelFormat::Nrrd: return writeFileAtomically(path, nrrdHeader(map, false) + gzipped(sampleBytes(map)));
    case LabelFormat::SlicerSegmentation:
        return writeFileAtomically(path, nrrdHeader(map, true) + gzipped(sampleBytes(map)));
    }
}

}  // namespace sculpt
