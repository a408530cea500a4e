// SPDX-License-Identifier: Apache-2.0
#include "core/io/stored_zip.h"

#include "core/base/errors.h"

#include <cstdint>
#include <fstream>
#include <limits>
#include <zlib.h>

namespace sculpt {

namespace {

constexpr std::uint16_t kVersion = 20;                       // 2.0: what stored entries need
constexpr std::uint16_t kUtf8Names = 1u << 11;               // general purpose flag: names are UTF-8
constexpr std::uint16_t kDosDate = (0 << 9) | (1 << 5) | 1;  // 1980-01-01: no clock in the bytes

/// Little-endian fields appended to a header.
class Fields {
public:
    Fields& u16(std::uint16_t v)
    {
        for (int i = 0; i < 2; ++i) mBytes.push_back(char(v >> (8 * i)));
        return *this;
    }
    Fields& u32(std::uint32_t v)
    {
        for (int i = 0; i < 4; ++i) mBytes.push_back(char(v >> (8 * i)));
        return *this;
    }
    Fields& text(const std::string& s)
    {
        mBytes += s;
        return *this;
    }
    const std::string& bytes() const { return mBytes; }

private:
    std::string mBytes;
};

/// The fields a local header and its central directory record share, from "version needed" on.
Fields& common(Fields& f, const ZipEntry& entry, std::uint32_t crc)
{
    const auto size = std::uint32_t(entry.bytes.size());
    return f.u16(kVersion)
        .u16(kUtf8Names)
        .u16(0)
        .u16(0)
        .u16(kDosDate)
        .u32(crc)
        .u32(size)
        .u32(size)
        .u16(std::uint16_t(entry.name.size()));
}

}  // namespace

void writeStoredZip(const std::vector<ZipEntry>& entries, const std::filesystem::path& path)
{
    double total = 22.0;
    for (const ZipEntry& entry : entries) total += double(entry.bytes.size()) + 2.0 * (46.0 + entry.name.size());
    if (total >= double(std::numeric_limits<std::uint32_t>::max()))
        throw InputError(path.string() + ": the archive would pass 4 GiB, more than a ZIP without ZIP64 holds");
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    Fields directory;
    std::uint32_t offset = 0;
    for (const ZipEntry& entry : entries) {
        const auto crc = std::uint32_t(
            crc32_z(crc32_z(0, nullptr, 0), reinterpret_cast<const Bytef*>(entry.bytes.data()), entry.bytes.size()));
        Fields local;
        common(local.u32(0x04034b50), entry, crc).u16(0).text(entry.name);
        out << local.bytes() << entry.bytes;
        common(directory.u32(0x02014b50).u16(kVersion), entry, crc)
            .u16(0)
            .u16(0)
            .u16(0)
            .u16(0)
            .u32(0)
            .u32(offset)
            .text(entry.name);
        offset += std::uint32_t(local.bytes().size() + entry.bytes.size());
    }
    Fields end;
    const auto count = std::uint16_t(entries.size());
    end.u32(0x06054b50)
        .u16(0)
        .u16(0)
        .u16(count)
        .u16(count)
        .u32(std::uint32_t(directory.bytes().size()))
        .u32(offset)
        .u16(0);
    out << directory.bytes() << end.bytes();
    out.flush();
    if (!out) throw InputError(path.string() + ": cannot write (disk full or not writable?)");
}

}  // namespace sculpt
