// SPDX-License-Identifier: Apache-2.0
// checkMetaImageHeader (header_checks.h): a MetaImage's text header and the samples it says it
// has; and metaImagePlacement (scan_frame.h): where the header places them.
#include "core/base/errors.h"
#include "core/scan/header_checks.h"
#include "core/scan/header_text.h"
#include "core/scan/sample_files.h"
#include "core/scan/scan_frame.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxMetaDimensions = 4;  // VTK reads three, with channels a fourth

double elementBytes(const std::string& type)
{
    static const std::map<std::string, double> bytes{{"MET_CHAR", 1},   {"MET_UCHAR", 1},     {"MET_SHORT", 2},
                                                     {"MET_USHORT", 2}, {"MET_INT", 4},       {"MET_UINT", 4},
                                                     {"MET_LONG", 8},   {"MET_ULONG", 8},     {"MET_FLOAT", 4},
                                                     {"MET_DOUBLE", 8}, {"MET_LONG_LONG", 8}, {"MET_ULONG_LONG", 8}};
    const auto found = bytes.find(type);
    return found == bytes.end() ? 0.0 : found->second;
}

/// NDims, and DimSize with that many sizes. @return the sample count.
double checkDimensions(const HeaderFields& fields, const std::string& where)
{
    const std::vector<double> ndims = fields.numbers("NDims", where);
    if (ndims.size() != 1 || !(ndims[0] >= 1 && ndims[0] <= kMaxMetaDimensions) || ndims[0] != std::floor(ndims[0]))
        throw InputError(where + "NDims '" + fields.text("NDims") + "' is not 1 to " +
                         std::to_string(kMaxMetaDimensions));
    const std::vector<double> sizes = fields.numbers("DimSize", where);
    if (sizes.size() != std::size_t(ndims[0]))
        throw InputError(where + "DimSize '" + fields.text("DimSize") + "' does not give NDims sizes");
    return sampleCount(sizes, where, "DimSize");
}

/// Every number that places the samples finite, spacings usable.
void checkPlacement(const HeaderFields& fields, const std::string& where)
{
    for (const char* key : {"Offset", "Position", "Origin", "TransformMatrix", "Rotation", "Orientation",
                            "CenterOfRotation", "ElementSize", "ElementMin", "ElementMax"})
        fields.numbers(key, where);
    requireSpacings(fields.numbers("ElementSpacing", where), where, "ElementSpacing");
}

/// The samples in `files` (the first's from `begin`): present, or inflating to their size.
void checkSamples(const HeaderFields& fields, const std::vector<fs::path>& files, double begin, double samples,
                  const std::string& where)
{
    const double element = elementBytes(fields.text("ElementType"));
    if (element == 0.0) throw InputError(where + "unknown ElementType '" + fields.text("ElementType") + "'");
    const std::vector<double> channels = fields.numbers("ElementNumberOfChannels", where);
    if (channels.size() > 1 || (!channels.empty() && !(channels[0] >= 1 && channels[0] <= 16)))
        throw InputError(where + "ElementNumberOfChannels '" + fields.text("ElementNumberOfChannels") +
                         "' is not 1 to 16");
    const double needed = samples * element * (channels.empty() ? 1.0 : channels[0]);
    const std::vector<double> skip = fields.numbers("HeaderSize", where);  // -1: the samples end the file
    const double available = bytesIn(files, begin);
    if (!skip.empty() && (skip.size() != 1 || skip[0] < -1.0 || skip[0] > available))
        throw InputError(where + "HeaderSize '" + fields.text("HeaderSize") + "' is not a skip within the data");
    const std::string compressed = fields.text("CompressedData");
    if (compressed == "True" || compressed == "true") {
        if (files.size() == 1) requireInflatesTo(files[0], std::uint64_t(begin), needed, where);
        return;
    }
    const double present = available - (skip.empty() ? 0.0 : std::max(0.0, skip[0]));
    if (present < needed) {
        throw InputError(where + "truncated: " + std::to_string((long long)std::max(0.0, present)) +
                         " bytes of samples where the header declares " + std::to_string((long long)needed));
    }
}

/// The header's lines, up to and including its ElementDataFile line, and their bytes; `in`
/// stays after them (a LIST's names follow).
std::vector<std::string> metaImageHeaderLines(std::ifstream& in, const std::string& where, std::size_t& bytes)
{
    std::string dataLine;
    std::vector<std::string> lines = headerLines(in, where, bytes, [&](const std::string& line) {
        if (trimmed(line).rfind("ElementDataFile", 0) != 0) return false;
        dataLine = line;
        return true;
    });
    if (dataLine.empty()) throw InputError(where + "the MetaImage header has no ElementDataFile line");
    lines.push_back(dataLine);
    return lines;
}

/// The first of `keys` the header has, as `count` numbers (`fallback` if none has it).
std::vector<double> firstOf(const HeaderFields& fields, std::initializer_list<const char*> keys, std::size_t count,
                            std::vector<double> fallback, const std::string& where)
{
    for (const char* key : keys) {
        if (!fields.has(key)) continue;
        std::vector<double> numbers = fields.numbers(key, where);
        if (numbers.size() < count)
            throw InputError(where + key + " '" + fields.text(key) + "' has fewer than " + std::to_string(count) +
                             " numbers");
        numbers.resize(count);
        return numbers;
    }
    return fallback;
}

std::ifstream openHeader(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the file");
    return in;
}

}  // namespace

ScanPlacement metaImagePlacement(const fs::path& path)
{
    const std::string where = path.string() + ": ";
    std::ifstream in = openHeader(path);
    std::size_t bytes = 0;
    const HeaderFields fields(metaImageHeaderLines(in, where, bytes), "=");
    const std::vector<double> ndims = fields.numbers("NDims", where);
    const std::size_t dims = ndims.empty() ? 3 : std::size_t(std::clamp(ndims[0], 1.0, 4.0));
    const std::size_t n = std::min<std::size_t>(dims, 3);  // the axes in space (a fourth: channels)
    const std::vector<double> origin =
        firstOf(fields, {"Offset", "Origin", "Position"}, n, std::vector<double>(n, 0.0), where);
    const std::vector<double> spacing = firstOf(fields, {"ElementSpacing"}, n, std::vector<double>(n, 1.0), where);
    std::vector<double> identity(dims * dims, 0.0);
    for (std::size_t a = 0; a < dims; ++a) identity[a * dims + a] = 1.0;
    // A row per axis: the direction of axis a is numbers a*dims .. (as ITK writes it).
    const std::vector<double> rows =
        firstOf(fields, {"TransformMatrix", "Rotation", "Orientation"}, dims * dims, identity, where);
    ScanPlacement placed;  // ITK's frame is LPS, in millimetres: nothing to convert
    for (std::size_t a = 0; a < n; ++a) {
        for (std::size_t c = 0; c < n; ++c) placed.worldFromIndex[int(a)][int(c)] = spacing[a] * rows[a * dims + c];
        placed.worldFromIndex[3][int(a)] = origin[a];
    }
    return placed;
}

void checkMetaImageHeader(const fs::path& path)
{
    const std::string where = path.string() + ": ";
    std::ifstream in = openHeader(path);
    // The header ends with its ElementDataFile line (included in `headerBytes`).
    std::size_t headerBytes = 0;
    const std::vector<std::string> lines = metaImageHeaderLines(in, where, headerBytes);
    const HeaderFields fields(lines, "=");
    const double samples = checkDimensions(fields, where);
    checkPlacement(fields, where);
    const std::string spec = fields.text("ElementDataFile");
    const bool local = spec == "LOCAL";
    std::size_t listBytes = 0;  // a LIST's names are the lines after it
    const std::vector<std::string> listLines =
        spec.rfind("LIST", 0) == 0 ? headerLines(in, where, listBytes, [](const std::string&) { return false; })
                                   : std::vector<std::string>{};
    const std::vector<fs::path> files =
        local ? std::vector<fs::path>{path} : dataFiles(spec, listLines, path.parent_path(), samples, where);
    checkSamples(fields, files, local ? double(headerBytes) : 0.0, samples, where);
}

}  // namespace sculpt
