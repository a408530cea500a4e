#include "core/scan/header_checks.h"

#include "core/base/errors.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

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

}  // namespace

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
