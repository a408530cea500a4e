// SPDX-License-Identifier: Apache-2.0
#include "core/scan/sample_files.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/scan/header_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <zlib.h>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

std::string wholeNumber(double n) { return std::to_string((long long)n); }

/// A file-name pattern with one integer conversion, formatted by us: the header's text is
/// never handed to printf.
class NamePattern {
public:
    NamePattern(const std::string& pattern, const std::string& where)
    {
        const auto percent = pattern.find('%');
        std::size_t at = percent + 1;
        mZeroPad = at < pattern.size() && pattern[at] == '0';
        while (at < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[at])) && at - percent < 4) {
            mWidth = mWidth * 10 + (pattern[at] - '0');
            ++at;
        }
        if (at >= pattern.size() || pattern[at] != 'd' || pattern.find('%', at) != std::string::npos)
            throw InputError(where + "the data file pattern '" + pattern + "' is not a name with one %d");
        mBefore = pattern.substr(0, percent);
        mAfter = pattern.substr(at + 1);
    }

    std::string operator()(long long n) const
    {
        std::string digits = std::to_string(std::llabs(n));
        if (digits.size() < std::size_t(mWidth))
            digits.insert(0, std::size_t(mWidth) - digits.size(), mZeroPad ? '0' : ' ');
        return mBefore + (n < 0 ? "-" : "") + digits + mAfter;
    }

private:
    std::string mBefore, mAfter;
    int mWidth = 0;
    bool mZeroPad = false;
};

std::vector<fs::path> patternFiles(std::istringstream& fields, const std::string& pattern, const fs::path& dir,
                                   double maxFiles, const std::string& where)
{
    const NamePattern name(pattern, where);
    double first = 0.0, last = 0.0, step = 0.0;
    if (!(fields >> first >> last >> step) || step == 0.0 || first != std::floor(first) || last != std::floor(last) ||
        step != std::floor(step) || std::abs(first) > 1e9 || std::abs(last) > 1e9)
        throw InputError(where + "the data file pattern '" + pattern +
                         "' needs a first, last and step (whole numbers)");
    const double count = std::floor((last - first) / step) + 1.0;
    if (!(count >= 1.0) || count > std::min(maxFiles, double(kMaxDataFiles)))
        throw InputError(where + "the data file pattern names " + formatNumber(count) + " files, where at most " +
                         wholeNumber(std::min(maxFiles, double(kMaxDataFiles))) + " can hold samples");
    std::vector<fs::path> files;
    for (double i = 0; i < count; ++i) files.push_back(dir / name((long long)(first + i * step)));
    return files;
}

}  // namespace

std::vector<fs::path> dataFiles(const std::string& spec, const std::vector<std::string>& listLines, const fs::path& dir,
                                double maxFiles, const std::string& where)
{
    std::istringstream fields(spec);
    std::string head;
    fields >> head;
    std::vector<fs::path> files;
    if (head == "LIST") {
        for (const std::string& line : listLines) {
            if (!trimmed(line).empty()) files.push_back(dir / trimmed(line));
        }
        if (files.empty() || double(files.size()) > std::min(maxFiles, double(kMaxDataFiles)))
            throw InputError(where + "the data file LIST names " + std::to_string(files.size()) + " files");
    } else if (spec.find('%') != std::string::npos) {
        files = patternFiles(fields, head, dir, maxFiles, where);
    } else {
        files.push_back(dir / spec);
    }
    for (const fs::path& file : files) {
        if (!fs::is_regular_file(file)) throw InputError(where + "its data file " + file.string() + " does not exist");
    }
    return files;
}

double bytesIn(const std::vector<fs::path>& files, double skip)
{
    double bytes = -skip;
    for (const fs::path& file : files) bytes += double(fs::file_size(file));
    return bytes;
}

void requireInflatesTo(const fs::path& file, std::uint64_t offset, double expected, const std::string& where)
{
    std::ifstream in(file, std::ios::binary);
    in.seekg(std::streamoff(offset));
    z_stream z{};
    if (inflateInit2(&z, 15 + 32) != Z_OK) throw std::runtime_error("zlib cannot start");  // 32: zlib or gzip
    std::vector<unsigned char> packed(1 << 16), unpacked(1 << 20);
    double inflated = 0.0;
    int status = Z_OK;
    while (status == Z_OK && inflated <= expected) {
        if (z.avail_in == 0) {
            in.read(reinterpret_cast<char*>(packed.data()), std::streamsize(packed.size()));
            z.next_in = packed.data();
            z.avail_in = uInt(in.gcount());
            if (z.avail_in == 0) break;  // the file ended before the stream did
        }
        z.next_out = unpacked.data();
        z.avail_out = uInt(unpacked.size());
        status = inflate(&z, Z_NO_FLUSH);
        inflated += double(unpacked.size() - z.avail_out);
        if (status == Z_BUF_ERROR) status = Z_OK;  // needs more input
    }
    const char* message = z.msg;
    inflateEnd(&z);
    if (status != Z_STREAM_END && status != Z_OK)
        throw InputError(where + "the compressed samples do not inflate (zlib: " + (message ? message : "corrupt") +
                         ")");
    if (status != Z_STREAM_END && inflated <= expected)
        throw InputError(where + "the compressed samples end early: " + wholeNumber(inflated) +
                         " bytes where the header declares " + wholeNumber(expected));
    if (inflated != expected)
        throw InputError(where + "the compressed samples inflate to " + (status == Z_STREAM_END ? "" : "more than ") +
                         wholeNumber(inflated) + " bytes where the header declares " + wholeNumber(expected));
}

}  // namespace sculpt
