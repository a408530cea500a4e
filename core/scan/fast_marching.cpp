// SPDX-License-Identifier: Apache-2.0
#include "core/scan/fast_marching.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculpt {

namespace {

/// The upwind solution of |grad d| = 1 from the smallest accepted neighbour distance along
/// each axis (+inf where none): the largest root that stays above the axes it uses.
float godunov(float a, float b, float c, float h)
{
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    float d = a + h;
    if (d <= b) return d;
    d = 0.5f * (a + b + std::sqrt(2.0f * h * h - (a - b) * (a - b)));
    if (d <= c) return d;
    const float s = a + b + c;
    return (s + std::sqrt(std::max(s * s - 3.0f * (a * a + b * b + c * c - h * h), 0.0f))) / 3.0f;
}

}  // namespace

void FastMarching::run(const openvdb::math::Coord& dims, float h, float limit, std::vector<float>& distance)
{
    enum State : unsigned char { Open, Seed, Accepted, Wall };
    const std::ptrdiff_t nx = dims.x(), ny = dims.y(), nz = dims.z();
    const std::ptrdiff_t stride[3] = {1, nx, nx * ny};
    const float width = h / 32.0f;
    const auto bucketOf = [&](float d) { return size_t(d / width); };
    mBuckets.resize(bucketOf(limit) + 1);
    for (auto& bucket : mBuckets) bucket.clear();
    // The faces are walls, so every marched voxel has its six neighbours inside the box.
    constexpr float kFar = std::numeric_limits<float>::infinity();
    mState.resize(distance.size());
    for (std::ptrdiff_t z = 0, i = 0; z < nz; ++z) {
        for (std::ptrdiff_t y = 0; y < ny; ++y) {
            for (std::ptrdiff_t x = 0; x < nx; ++x, ++i) {
                const bool face = x == 0 || y == 0 || z == 0 || x == nx - 1 || y == ny - 1 || z == nz - 1;
                mState[size_t(i)] = face ? Wall : distance[size_t(i)] < kFar ? Seed : Open;
                if (!face && distance[size_t(i)] < limit)
                    mBuckets[bucketOf(distance[size_t(i)])].push_back(std::uint32_t(i));
            }
        }
    }
    const auto acceptedAlong = [&](size_t i, std::ptrdiff_t step) {
        const float below = mState[i - size_t(step)] == Accepted ? distance[i - size_t(step)] : kFar;
        const float above = mState[i + size_t(step)] == Accepted ? distance[i + size_t(step)] : kFar;
        return std::min(below, above);
    };
    // Gives the open neighbours of voxel i their distance through it.
    const auto updateNeighbours = [&](size_t i) {
        for (const std::ptrdiff_t offset : {-stride[0], stride[0], -stride[1], stride[1], -stride[2], stride[2]}) {
            const size_t j = size_t(std::ptrdiff_t(i) + offset);
            if (mState[j] != Open) continue;
            const float u =
                godunov(acceptedAlong(j, stride[0]), acceptedAlong(j, stride[1]), acceptedAlong(j, stride[2]), h);
            if (u < distance[j]) {
                distance[j] = u;
                if (u < limit) mBuckets[bucketOf(u)].push_back(std::uint32_t(j));
            }
        }
    };
    // A voxel's new distance exceeds its accepted neighbour's by h / sqrt(3) or more: it always
    // lands in a later bucket than the one being emptied.
    for (size_t b = 0; b < mBuckets.size(); ++b) {
        while (!mBuckets[b].empty()) {
            const std::uint32_t i = mBuckets[b].back();
            mBuckets[b].pop_back();
            if (mState[i] == Accepted || bucketOf(distance[i]) != b) continue;  // stale entry
            mState[i] = Accepted;
            updateNeighbours(i);
        }
    }
}

}  // namespace sculpt
