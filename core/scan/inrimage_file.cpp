// SPDX-License-Identifier: Apache-2.0
#include "core/scan/inrimage_file.h"

#include "core/base/errors.h"
#include "core/scan/header_text.h"
#include "core/scan/vtk_image_scan.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkType.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <zlib.h>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMagic = "#INRIMAGE-4#{";
constexpr const char* kEnd = "##}";

/// What the header declares.
struct InrLayout {
    int dims[3] = {0, 0, 0};
    int vtkType = VTK_UNSIGNED_CHAR;
    bool bigEndian = false;
    double spacing[3] = {1.0, 1.0, 1.0};
    double sampleBytes = 0.0;
};

/// A gzip or plain file read through zlib (gzread passes plain files through).
class GzReader {
public:
    explicit GzReader(const fs::path& path) : mPath(path), mFile(gzopen(path.string().c_str(), "rb"))
    {
        if (!mFile) throw InputError(path.string() + ": cannot read the file");
    }
    ~GzReader() { gzclose(mFile); }
    GzReader(const GzReader&) = delete;
    GzReader& operator=(const GzReader&) = delete;

    /// Up to `bytes` bytes into `into`. @return how many came (fewer: the end of the data).
    std::size_t read(char* into, std::size_t bytes)
    {
        std::size_t done = 0;
        while (done < bytes) {
            const unsigned ask = unsigned(std::min<std::size_t>(bytes - done, 1u << 30));
            const int got = gzread(mFile, into + done, ask);
            if (got < 0) {
                int error = Z_OK;
                const std::string message = gzerror(mFile, &error);
                if (error == Z_BUF_ERROR) break;  // the file ends inside the stream: truncated
                throw InputError(mPath.string() + ": the compressed data does not inflate (zlib: " + message + ")");
            }
            if (got == 0) break;
            done += std::size_t(got);
        }
        return done;
    }

private:
    fs::path mPath;
    gzFile mFile;
};

int sampleType(const std::string& type, double bits, const std::string& where)
{
    const bool isFloat = type == "float";
    const bool isSigned = type == "signed fixed";
    if (!isFloat && !isSigned && type != "unsigned fixed")
        throw InputError(where + "TYPE '" + type + "' is not unsigned fixed, signed fixed or float");
    if (isFloat && bits == 32) return VTK_FLOAT;
    if (isFloat && bits == 64) return VTK_DOUBLE;
    if (!isFloat && bits == 8) return isSigned ? VTK_SIGNED_CHAR : VTK_UNSIGNED_CHAR;
    if (!isFloat && bits == 16) return isSigned ? VTK_SHORT : VTK_UNSIGNED_SHORT;
    if (!isFloat && bits == 32) return isSigned ? VTK_INT : VTK_UNSIGNED_INT;
    throw InputError(where + "PIXSIZE " + std::to_string(int(bits)) + " bits is not one we read for TYPE " + type);
}

/// One number of a field, or `fallback` if the header lacks it.
double number(const HeaderFields& fields, const std::string& key, double fallback, const std::string& where)
{
    if (!fields.has(key)) return fallback;
    const std::vector<double> values = fields.numbers(key, where);
    if (values.size() != 1) throw InputError(where + key + " is not one number");
    return values.front();
}

InrLayout readLayout(GzReader& in, const fs::path& path)
{
    const std::string where = path.string() + ": ";
    // The header is read in its 256-byte blocks until one holds the end mark.
    std::string header;
    std::size_t end = std::string::npos;
    char block[256];
    while (end == std::string::npos) {
        const std::size_t got = in.read(block, sizeof block);
        header.append(block, got);
        if (header.compare(0, std::string(kMagic).size(), kMagic) != 0)
            throw InputError(where + "not an INRIMAGE-4 file (it does not begin with " + kMagic + ")");
        end = header.find(std::string("\n") + kEnd);
        if (got < sizeof block && end == std::string::npos) throw InputError(where + "the header never ends (no ##})");
        if (header.size() > kMaxHeaderBytes) throw InputError(where + "the header is longer than 64 KiB");
    }
    if (header.find('\0') < end) throw InputError(where + "the header holds a NUL byte");
    std::vector<std::string> lines;
    for (std::size_t at = header.find('\n') + 1; at < end + 1;) {
        const std::size_t next = header.find('\n', at);
        lines.push_back(trimmed(header.substr(at, next - at)));
        at = next + 1;
    }
    const HeaderFields fields(lines, "=");
    InrLayout layout;
    // XDIM and YDIM are required, ZDIM 1 (a slice) if absent.
    const std::vector<double> sizes{number(fields, "XDIM", -1, where), number(fields, "YDIM", -1, where),
                                    number(fields, "ZDIM", 1, where)};
    const double samples = sampleCount(sizes, where, "XDIM, YDIM, ZDIM");
    if (number(fields, "VDIM", 1, where) != 1)
        throw InputError(where + "VDIM " + fields.text("VDIM") + ": only scans of one value per sample are read");
    const std::string bits = fields.text("PIXSIZE");
    layout.vtkType = sampleType(trimmed(fields.text("TYPE")), std::atof(bits.c_str()), where);
    const std::string cpu = trimmed(fields.text("CPU"));
    if (cpu != "decm" && cpu != "alpha" && cpu != "pc" && cpu != "sun" && cpu != "sgi" && !cpu.empty())
        throw InputError(where + "CPU '" + cpu + "' names no byte order we know (decm, alpha, pc, sun, sgi)");
    layout.bigEndian = cpu == "sun" || cpu == "sgi";
    const std::vector<double> spacing{number(fields, "VX", 1, where), number(fields, "VY", 1, where),
                                      number(fields, "VZ", 1, where)};
    requireSpacings(spacing, where, "VX, VY, VZ");
    for (int a = 0; a < 3; ++a) {
        layout.dims[a] = int(sizes[std::size_t(a)]);
        layout.spacing[a] = std::abs(spacing[std::size_t(a)]);
    }
    // The samples start after the block holding the end mark: where reading the header stopped.
    layout.sampleBytes = samples * vtkDataArray::GetDataTypeSize(layout.vtkType);
    return layout;
}

}  // namespace

void checkInrimageHeader(const fs::path& path)
{
    GzReader in(path);
    const InrLayout layout = readLayout(in, path);
    // Every sample declared must be there: inflated as far as they go, no further.
    std::vector<char> buffer(1 << 20);
    double have = 0.0;
    for (std::size_t got = 1; got > 0 && have < layout.sampleBytes;) {
        got = in.read(buffer.data(), std::size_t(std::min(double(buffer.size()), layout.sampleBytes - have)));
        have += double(got);
    }
    if (have < layout.sampleBytes)
        throw InputError(path.string() + ": truncated (" + std::to_string(std::uint64_t(have)) + " bytes of samples, " +
                         std::to_string(std::uint64_t(layout.sampleBytes)) + " declared)");
}

ScanVolume readInrimage(const fs::path& path)
{
    GzReader in(path);
    const InrLayout layout = readLayout(in, path);
    vtkNew<vtkImageData> image;
    image->SetDimensions(layout.dims[0], layout.dims[1], layout.dims[2]);
    image->SetSpacing(layout.spacing[0], layout.spacing[1], layout.spacing[2]);
    image->AllocateScalars(layout.vtkType, 1);
    char* samples = static_cast<char*>(image->GetScalarPointer());
    if (in.read(samples, std::size_t(layout.sampleBytes)) < std::size_t(layout.sampleBytes))
        throw InputError(path.string() + ": truncated (fewer samples than its header declares)");
    if (layout.bigEndian) {
        const int size = vtkDataArray::GetDataTypeSize(layout.vtkType);
        for (double at = 0; at < layout.sampleBytes; at += size)
            std::reverse(samples + std::size_t(at), samples + std::size_t(at) + size);
    }
    vtkSmartPointer<vtkImageData> kept = image.Get();
    return makeScan(kept, placement(kept, nullptr), path.string(),
                    {path.string() + ": INRIMAGE declares no patient frame: taken as LPS millimetres"});
}

}  // namespace sculpt
