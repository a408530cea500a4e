// SPDX-License-Identifier: Apache-2.0
#include "core/io/content_uuid.h"

#include "core/base/errors.h"

#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>

namespace sculpt {

namespace {

// The header: magic (8 bytes), file version and library version (3 x 4), "has grid offsets" (1),
// then the UUID as 36 characters ("xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx").
constexpr std::size_t kUuidOffset = 21, kUuidLength = 36;

bool looksLikeUuid(const char* text)
{
    for (std::size_t i = 0; i < kUuidLength; ++i) {
        const bool hyphen = i == 8 || i == 13 || i == 18 || i == 23;
        if (hyphen != (text[i] == '-')) return false;
        if (!hyphen && !std::isxdigit(static_cast<unsigned char>(text[i]))) return false;
    }
    return true;
}

/// Two lanes of FNV-1a over 8-byte words: fast (a few GB/s) and stable across platforms; an
/// identifier, not a defence against forgery.
class ContentHash {
public:
    void add(const char* data, std::size_t bytes)
    {
        for (; bytes > 0; ++data, --bytes) {  // bytes gather into words
            mWord |= std::uint64_t(static_cast<unsigned char>(*data)) << (8 * mFill);
            if (++mFill == 8) flushWord();
        }
    }
    std::array<std::uint64_t, 2> finish()
    {
        mWord ^= std::uint64_t(mFill) << 56;  // a short tail differs from zero bytes
        flushWord();
        return mLanes;
    }

private:
    void flushWord()
    {
        constexpr std::uint64_t kPrime = 0x100000001b3ULL;
        mLanes[0] = (mLanes[0] ^ mWord) * kPrime;
        mLanes[1] = (mLanes[1] ^ (mWord >> 32 | mWord << 32)) * kPrime;
        mWord = 0;
        mFill = 0;
    }

    std::array<std::uint64_t, 2> mLanes{0xcbf29ce484222325ULL, 0x84222325cbf29ce4ULL};
    std::uint64_t mWord = 0;
    int mFill = 0;
};

std::string formatUuid(std::array<std::uint64_t, 2> bits)
{
    bits[0] = (bits[0] & ~0xf000ULL) | 0x5000ULL;                         // version 5: name-based
    bits[1] = (bits[1] & 0x3fffffffffffffffULL) | 0x8000000000000000ULL;  // RFC 4122 variant
    char text[kUuidLength + 1];
    std::snprintf(text, sizeof text, "%08x-%04x-%04x-%04x-%012llx", unsigned(bits[0] >> 32),
                  unsigned(bits[0] >> 16 & 0xffff), unsigned(bits[0] & 0xffff), unsigned(bits[1] >> 48),
                  static_cast<unsigned long long>(bits[1] & 0xffffffffffffULL));
    return text;
}

}  // namespace

void stampContentUuid(const std::filesystem::path& file)
{
    std::fstream io(file, std::ios::in | std::ios::out | std::ios::binary);
    std::vector<char> buffer(1 << 20);
    io.read(buffer.data(), std::streamsize(kUuidOffset + kUuidLength));
    if (io.gcount() != std::streamsize(kUuidOffset + kUuidLength) || !looksLikeUuid(buffer.data() + kUuidOffset))
        throw InputError(file.string() + ": cannot write (no UUID in the header OpenVDB wrote)");
    ContentHash hash;
    hash.add(buffer.data(), kUuidOffset);
    while (io.read(buffer.data(), std::streamsize(buffer.size())) || io.gcount() > 0)
        hash.add(buffer.data(), std::size_t(io.gcount()));
    io.clear();
    const std::string uuid = formatUuid(hash.finish());
    io.seekp(std::streamoff(kUuidOffset));
    io.write(uuid.data(), std::streamsize(kUuidLength));
    io.flush();
    if (!io) throw InputError(file.string() + ": cannot write (disk full or not writable?)");
}

}  // namespace sculpt
