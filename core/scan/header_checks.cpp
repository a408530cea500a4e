#include "core/scan/header_checks.h"

#include "core/base/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include <zlib.h>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
constexpr double kMaxSamples = double(1LL << 40);

std::string trimmed(const std::string& text)
{
    const auto first = text.find_first_not_of(" \t\r");
    const auto last = text.find_last_not_of(" \t\r");
    return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

double elementBytes(const std::string& type)
{
    static const std::map<std::string, double> bytes{{"MET_CHAR", 1},   {"MET_UCHAR", 1},     {"MET_SHORT", 2},
                                                     {"MET_USHORT", 2}, {"MET_INT", 4},       {"MET_UINT", 4},
                                                     {"MET_LONG", 8},   {"MET_ULONG", 8},     {"MET_FLOAT", 4},
                                                     {"MET_DOUBLE", 8}, {"MET_LONG_LONG", 8}, {"MET_ULONG_LONG", 8}};
    const auto found = bytes.find(type);
    return found == bytes.end() ? 0.0 : found->second;
}

/// Field `key` as a number, `fallback` if absent. @throws InputError if it is not one.
double numberField(std::map<std::string, std::string>& fields, const std::string& key, double fallback,
                   const std::string& where)
{
    if (!fields.count(key)) return fallback;
    std::istringstream text(fields[key]);
    double value = 0.0;
    if (!(text >> value) || !std::isfinite(value))
        throw InputError(where + key + " '" + fields[key] + "' is not a number");
    return value;
}

/// The header lines up to (not including) the line `isEnd` is true for, or to the end of the
/// file; their bytes in `bytes`.
std::vector<std::string> headerLines(std::istream& in, const std::string& where, std::size_t& bytes,
                                     const std::function<bool(const std::string&)>& isEnd)
{
    std::vector<std::string> lines;
    bytes = 0;
    for (std::string line;;) {
        if (!std::getline(in, line)) return lines;  // a detached header may end with the file
        bytes += line.size() + 1;
        if (bytes > kMaxHeaderBytes || line.find('\0') != std::string::npos)
            throw InputError(where + "not a text header (binary bytes, or no end within 64 KiB)");
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (isEnd(line)) return lines;
        lines.push_back(line);
    }
}

/// The product of the whitespace-separated positive integers in `text`; 0 if there are none
/// or one is not a positive integer.
double sizeProduct(const std::string& text, int& count)
{
    std::istringstream in(text);
    double product = 1.0;
    count = 0;
    for (double d; in >> d; ++count) {
        if (!(d >= 1.0) || d != std::floor(d)) return 0.0;
        product *= d;
    }
    return count ? product : 0.0;
}

}  // namespace

void checkNrrdHeader(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the file");
    const std::string where = path.string() + ": ";
    std::string magic;
    std::getline(in, magic);
    if (magic.rfind("NRRD000", 0) != 0) throw InputError(where + "not a NRRD file (it must start with NRRD000)");
    std::size_t bytes = 0;
    std::map<std::string, std::string> fields;
    for (const std::string& line : headerLines(in, where, bytes, [](const std::string& l) { return l.empty(); })) {
        if (line[0] == '#') continue;
        const auto colon = line.find(':');
        if (colon != std::string::npos && line.compare(colon, 2, ":=") != 0)
            fields[trimmed(line.substr(0, colon))] = trimmed(line.substr(colon + 1));
    }
    bytes += magic.size() + 1;
    static const std::map<std::string, double> typeBytes{
        {"uchar", 1},   {"unsigned char", 1}, {"uint8", 1},          {"uint8_t", 1}, {"signed char", 1},
        {"int8", 1},    {"int8_t", 1},        {"char", 1},           {"short", 2},   {"int16", 2},
        {"int16_t", 2}, {"ushort", 2},        {"unsigned short", 2}, {"uint16", 2},  {"uint16_t", 2},
        {"int", 4},     {"int32", 4},         {"int32_t", 4},        {"uint", 4},    {"unsigned int", 4},
        {"uint32", 4},  {"uint32_t", 4},      {"float", 4},          {"double", 8}};
    const auto type = typeBytes.find(fields["type"]);
    if (type == typeBytes.end()) throw InputError(where + "unknown or missing sample type '" + fields["type"] + "'");
    if (!fields.count("sizes")) throw InputError(where + "the header has no 'sizes:' line");
    int count = 0;
    const double samples = sizeProduct(fields["sizes"], count);
    if (samples == 0.0 || samples > kMaxSamples)
        throw InputError(where + "sizes '" + fields["sizes"] + "' is no scan's size");
    if (fields.count("dimension") && fields["dimension"] != std::to_string(count))
        throw InputError(where + "dimension " + fields["dimension"] + " but " + std::to_string(count) + " sizes");
    const std::string encoding = fields.count("encoding") ? fields["encoding"] : "raw";
    const std::string dataFile = fields.count("data file") ? fields["data file"] : fields["datafile"];
    if (dataFile.rfind("LIST", 0) == 0 || dataFile.find('%') != std::string::npos) return;  // slice lists
    const fs::path data = dataFile.empty() ? path : path.parent_path() / dataFile;
    if (!fs::exists(data)) throw InputError(where + "its data file " + data.string() + " does not exist");
    if (encoding != "raw") return;  // compressed: the reader's decompression reports a short file
    const double available = double(fs::file_size(data)) - (dataFile.empty() ? double(bytes) : 0.0);
    const double needed = samples * type->second;
    if (available < needed) {
        throw InputError(where + "truncated: " + std::to_string((long long)std::max(0.0, available)) +
                         " bytes of samples where the header declares " + std::to_string((long long)needed));
    }
}

namespace {

/// NIfTI-1 datatypes VTK reads, with their bits per voxel.
const std::map<int, int>& niftiBits()
{
    static const std::map<int, int> bits{{2, 8},   {4, 16},   {8, 32},   {16, 32},   {64, 64},   {128, 24},
                                         {256, 8}, {512, 16}, {768, 32}, {1024, 64}, {1280, 64}, {2304, 32}};
    return bits;
}

/// A gzip (or plain) file read through zlib: its first bytes, then how long it is, up to `enough`.
struct Unzipped {
    std::string head;
    double length = 0.0;  // at most `enough`
};

Unzipped readThroughZlib(const fs::path& path, std::size_t headBytes, double enough)
{
    gzFile file = gzopen(path.string().c_str(), "rb");
    if (!file) throw InputError(path.string() + ": cannot read the file");
    Unzipped out;
    std::vector<char> buffer(1 << 20);
    while (out.length < enough) {
        const int got = gzread(file, buffer.data(), unsigned(buffer.size()));
        if (got <= 0) break;  // the end, or a corrupt stream: either way no more samples
        if (out.head.size() < headBytes)
            out.head.append(buffer.data(), std::min<std::size_t>(std::size_t(got), headBytes - out.head.size()));
        out.length += got;
    }
    gzclose(file);
    return out;
}

template <typename T>
T valueAt(const std::string& bytes, std::size_t offset, bool swapped)
{
    T value;
    std::string raw = bytes.substr(offset, sizeof(T));
    if (swapped) std::reverse(raw.begin(), raw.end());
    std::memcpy(&value, raw.data(), sizeof(T));
    return value;
}

}  // namespace

void checkNiftiHeader(const fs::path& path)
{
    const std::string where = path.string() + ": ";
    constexpr std::size_t kHeader = 348;
    // First the header alone, then (knowing what it declares) the length, read to that point.
    const Unzipped first = readThroughZlib(path, kHeader, double(kHeader));
    if (first.head.size() < kHeader) throw InputError(where + "too short for a NIfTI header");
    const std::string& h = first.head;
    const int size = valueAt<std::int32_t>(h, 0, false);
    if (size == 540 || valueAt<std::int32_t>(h, 0, true) == 540) return;  // NIfTI-2: VTK checks it
    const bool swapped = size != 348;
    if (swapped && valueAt<std::int32_t>(h, 0, true) != 348) throw InputError(where + "not a NIfTI-1 file");
    const int dims = valueAt<std::int16_t>(h, 40, swapped);
    if (dims < 1 || dims > 7) throw InputError(where + "the header gives " + std::to_string(dims) + " dimensions");
    double samples = 1.0;
    for (int k = 1; k <= dims; ++k) {
        const int n = valueAt<std::int16_t>(h, std::size_t(40 + 2 * k), swapped);
        if (n < 1) throw InputError(where + "dimension " + std::to_string(k) + " has size " + std::to_string(n));
        samples *= n;
    }
    const int datatype = valueAt<std::int16_t>(h, 70, swapped), bitpix = valueAt<std::int16_t>(h, 72, swapped);
    const auto known = niftiBits().find(datatype);
    if (known == niftiBits().end()) throw InputError(where + "unknown NIfTI datatype " + std::to_string(datatype));
    if (known->second != bitpix)
        throw InputError(where + "datatype " + std::to_string(datatype) + " with " + std::to_string(bitpix) +
                         " bits per voxel");
    const float voxOffset = valueAt<float>(h, 108, swapped);
    if (h.compare(344, 3, "n+1") != 0) return;  // a .hdr/.img pair: the image file is VTK's to check
    if (!(voxOffset >= 352.f) || !std::isfinite(voxOffset)) throw InputError(where + "bad vox_offset in the header");
    const double needed = double(voxOffset) + samples * bitpix / 8.0;
    const Unzipped all = readThroughZlib(path, 0, needed);
    if (all.length < needed) {
        throw InputError(where + "truncated: " + std::to_string((long long)all.length) +
                         " bytes where the header declares " + std::to_string((long long)needed));
    }
}

void checkMetaImageHeader(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the file");
    const std::string where = path.string() + ": ";
    std::map<std::string, std::string> fields;
    std::size_t headerBytes = 0;
    std::string line;
    while (fields.count("ElementDataFile") == 0) {
        if (!std::getline(in, line)) throw InputError(where + "the MetaImage header has no ElementDataFile line");
        headerBytes += line.size() + 1;
        if (headerBytes > kMaxHeaderBytes || line.find('\0') != std::string::npos)
            throw InputError(where + "not a MetaImage header (binary bytes, or no end within 64 KiB)");
        const auto equals = line.find('=');
        if (equals != std::string::npos) fields[trimmed(line.substr(0, equals))] = trimmed(line.substr(equals + 1));
    }
    std::istringstream dimText(fields["DimSize"]);
    double samples = 1.0;
    int dims = 0;
    for (double d; dimText >> d; ++dims) {
        if (!(d >= 1.0) || d != std::floor(d)) throw InputError(where + "DimSize holds " + fields["DimSize"]);
        samples *= d;
    }
    if (dims == 0 || samples > kMaxSamples)
        throw InputError(where + "DimSize '" + fields["DimSize"] + "' is no scan's size");
    const double element = elementBytes(fields["ElementType"]);
    if (element == 0.0) throw InputError(where + "unknown ElementType '" + fields["ElementType"] + "'");
    const double channels = numberField(fields, "ElementNumberOfChannels", 1.0, where);
    const double needed = samples * element * std::max(1.0, channels);
    const bool compressed = fields["CompressedData"] == "True" || fields["CompressedData"] == "true";
    const std::string& dataFile = fields["ElementDataFile"];
    if (dataFile == "LIST" || dataFile.find('%') != std::string::npos) return;  // slice lists: the reader checks
    const bool local = dataFile == "LOCAL";
    const fs::path data = local ? path : path.parent_path() / dataFile;
    if (!fs::exists(data)) throw InputError(where + "its data file " + data.string() + " does not exist");
    const double available = double(fs::file_size(data)) - (local ? double(headerBytes) : 0.0);
    const double declared = compressed ? numberField(fields, "CompressedDataSize", 0.0, where) : needed;
    if (available < declared) {
        throw InputError(where + "truncated: " + std::to_string((long long)available) +
                         " bytes of samples where the header declares " + std::to_string((long long)declared));
    }
}

}  // namespace sculpt
