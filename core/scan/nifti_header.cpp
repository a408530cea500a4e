// SPDX-License-Identifier: Apache-2.0
// checkNiftiHeader (header_checks.h): the NIfTI-1 header's fields, at their fixed offsets.
#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/scan/header_checks.h"
#include "core/scan/header_text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>
#include <zlib.h>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kHeaderBytes = 348;

/// NIfTI-1 datatypes VTK reads, with their bits per voxel.
const std::map<int, int>& niftiBits()
{
    static const std::map<int, int> bits{{2, 8},   {4, 16},   {8, 32},   {16, 32},   {64, 64},   {128, 24},
                                         {256, 8}, {512, 16}, {768, 32}, {1024, 64}, {1280, 64}, {2304, 32}};
    return bits;
}

/// A .nii or .nii.gz read through zlib: its first bytes, and how long it is.
struct Unzipped {
    std::string head;
    double length = 0.0;
};

/// Reads `headBytes`, or (`whole`) on to the end, which checks a gzip stream's CRC, stopping
/// past `cap` bytes (a stream inflating without end). @throws InputError if it does not inflate.
Unzipped readThroughZlib(const fs::path& path, std::size_t headBytes, bool whole, double cap)
{
    gzFile file = gzopen(path.string().c_str(), "rb");
    if (!file) throw InputError(path.string() + ": cannot read the file");
    Unzipped out;
    std::vector<char> buffer(whole ? 1 << 20 : headBytes);
    int got = 0;
    while ((whole ? out.length <= cap : out.head.size() < headBytes) &&
           (got = gzread(file, buffer.data(), unsigned(buffer.size()))) > 0) {
        if (out.head.size() < headBytes)
            out.head.append(buffer.data(), std::min<std::size_t>(std::size_t(got), headBytes - out.head.size()));
        out.length += got;
    }
    int error = Z_OK;
    const std::string message = got < 0 ? gzerror(file, &error) : "";
    gzclose(file);
    if (got < 0 && error != Z_BUF_ERROR)  // Z_BUF_ERROR: the file ends inside the stream (truncated)
        throw InputError(path.string() + ": the compressed data does not inflate (zlib: " + message + ")");
    return out;
}

/// The header's fields, in its byte order.
class NiftiFields {
public:
    explicit NiftiFields(std::string bytes) : mBytes(std::move(bytes)) {}

    bool swapped() const { return mSwapped; }
    void setSwapped(bool swapped) { mSwapped = swapped; }

    template <typename T>
    T at(std::size_t offset) const
    {
        char raw[sizeof(T)];
        std::memcpy(raw, mBytes.data() + offset, sizeof(T));
        if (mSwapped) std::reverse(raw, raw + sizeof(T));
        T value;
        std::memcpy(&value, raw, sizeof(T));
        return value;
    }

    /// `count` floats from `offset`. @throws InputError naming `field` if one is not finite.
    std::vector<double> finite(std::size_t offset, int count, const std::string& where, const char* field) const
    {
        std::vector<double> values;
        for (int i = 0; i < count; ++i) {
            const float v = at<float>(offset + 4 * std::size_t(i));
            if (!std::isfinite(v))
                throw InputError(where + field + " holds " + formatNumber(v) + ": not a finite number");
            values.push_back(v);
        }
        return values;
    }

    bool magic(const char* text) const { return mBytes.compare(344, 3, text) == 0; }

private:
    std::string mBytes;
    bool mSwapped = false;
};

/// The sample count, from dim[0..7]. @throws InputError for no sane dimensions.
double niftiSamples(const NiftiFields& h, const std::string& where)
{
    const int dims = h.at<std::int16_t>(40);
    if (dims < 1 || dims > 7) throw InputError(where + "the header gives " + std::to_string(dims) + " dimensions");
    std::vector<double> sizes;
    for (int k = 1; k <= dims; ++k) sizes.push_back(h.at<std::int16_t>(std::size_t(40 + 2 * k)));
    return sampleCount(sizes, where, "dim");
}

/// Spacing, scaling and both orientations: every number finite and usable.
void checkGeometry(const NiftiFields& h, const std::string& where)
{
    const int dims = h.at<std::int16_t>(40);
    const std::vector<double> pixdim = h.finite(76, 8, where, "pixdim");
    requireSpacings({pixdim.begin() + 1, pixdim.begin() + 1 + std::min(dims, 3)}, where, "pixdim");
    h.finite(112, 2, where, "scl_slope and scl_inter");
    h.finite(256, 3, where, "quatern_b/c/d");  // readers normalise a quaternion longer than 1
    h.finite(268, 3, where, "qoffset");
    const std::vector<double> srow = h.finite(280, 12, where, "srow_x/y/z");
    if (h.at<std::int16_t>(254) > 0) {
        for (int column = 0; column < 3; ++column) {
            const double length = std::sqrt(srow[std::size_t(column)] * srow[std::size_t(column)] +
                                            srow[std::size_t(4 + column)] * srow[std::size_t(4 + column)] +
                                            srow[std::size_t(8 + column)] * srow[std::size_t(8 + column)]);
            requireSpacings({length}, where, "srow_x/y/z");
        }
    }
}

}  // namespace

void checkNiftiHeader(const fs::path& path)
{
    const std::string where = path.string() + ": ";
    // First the header alone, then (knowing what it declares) the length, read to that point.
    const Unzipped first = readThroughZlib(path, kHeaderBytes, /*whole=*/false, 0.0);
    if (first.head.size() < kHeaderBytes) throw InputError(where + "too short for a NIfTI header");
    NiftiFields h(first.head);
    const int size = h.at<std::int32_t>(0);
    h.setSwapped(true);
    if (size == 540 || h.at<std::int32_t>(0) == 540) return;  // NIfTI-2: VTK checks it
    h.setSwapped(size != 348);
    if (h.at<std::int32_t>(0) != 348) throw InputError(where + "not a NIfTI-1 file");
    const double samples = niftiSamples(h, where);
    const int datatype = h.at<std::int16_t>(70), bitpix = h.at<std::int16_t>(72);
    const auto known = niftiBits().find(datatype);
    if (known == niftiBits().end()) throw InputError(where + "unknown NIfTI datatype " + std::to_string(datatype));
    if (known->second != bitpix)
        throw InputError(where + "datatype " + std::to_string(datatype) + " with " + std::to_string(bitpix) +
                         " bits per voxel");
    checkGeometry(h, where);
    const float voxOffset = h.at<float>(108);
    if (!h.magic("n+1")) return;  // a .hdr/.img pair: the image file is VTK's to check
    if (!(voxOffset >= 352.f) || !std::isfinite(voxOffset)) throw InputError(where + "bad vox_offset in the header");
    const double needed = double(voxOffset) + samples * bitpix / 8.0;
    const Unzipped all = readThroughZlib(path, 0, /*whole=*/true, 2.0 * needed + double(1 << 20));
    if (all.length < needed) {
        throw InputError(where + "truncated: " + std::to_string((long long)all.length) +
                         " bytes where the header declares " + std::to_string((long long)needed));
    }
}

}  // namespace sculpt
