// SPDX-License-Identifier: Apache-2.0
#include "core/io/point_cache_file.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/io/byte_order.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

namespace sculpt {

namespace {

constexpr char kSignature[12] = "POINTCACHE2";  // with its terminating zero: 12 bytes
constexpr std::size_t kHeaderBytes = 12 + 4 + 4 + 4 + 4 + 4;

}  // namespace

void writePointCache(const PointCache& cache, const std::filesystem::path& path)
{
    const std::size_t points = cache.samples.empty() ? 0 : cache.samples.front().size();
    std::string bytes(kSignature, kSignature + sizeof(kSignature));
    appendLittle(bytes, std::int32_t(1));
    appendLittle(bytes, std::int32_t(points));
    appendLittle(bytes, cache.startFrame);
    appendLittle(bytes, cache.sampleRate);
    appendLittle(bytes, std::int32_t(cache.samples.size()));
    bytes.reserve(kHeaderBytes + cache.samples.size() * points * 12);
    for (const auto& sample : cache.samples) {
        if (sample.size() != points)
            throw InputError(path.string() + ": a point cache's samples must all have " + std::to_string(points) +
                             " points (one has " + std::to_string(sample.size()) + ")");
        for (const auto& p : sample)
            for (const float c : p) appendLittle(bytes, c);
    }
    writeFileAtomically(path, bytes);
}

PointCache readPointCache(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot open the point cache");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kSignature, sizeof(kSignature)) != 0)
        throw InputError(path.string() + ": not a point cache (no POINTCACHE2 header)");
    const char* at = bytes.data() + sizeof(kSignature);
    const auto version = readStored<std::int32_t>(at, false);
    const auto points = readStored<std::int32_t>(at + 4, false);
    PointCache cache;
    cache.startFrame = readStored<float>(at + 8, false);
    cache.sampleRate = readStored<float>(at + 12, false);
    const auto samples = readStored<std::int32_t>(at + 16, false);
    if (version != 1 || points < 0 || samples < 0 ||
        bytes.size() != kHeaderBytes + std::size_t(points) * std::size_t(samples) * 12)
        throw InputError(path.string() + ": the point cache's size is not what its header declares");
    at = bytes.data() + kHeaderBytes;
    cache.samples.assign(std::size_t(samples), std::vector<std::array<float, 3>>(std::size_t(points)));
    for (auto& sample : cache.samples)
        for (auto& p : sample)
            for (float& c : p) c = readStored<float>(at, false), at += 4;
    return cache;
}

}  // namespace sculpt
