// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file byte_order.h
/// @brief Numbers as binary formats store them, in either byte order.

#include <algorithm>
#include <cstring>

namespace sculpt {

inline bool hostIsBigEndian()
{
    const unsigned probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    return first == 0;
}

/// The T stored at `at` (unaligned) in big- or little-endian order.
template <typename T>
T readStored(const char* at, bool bigEndian)
{
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, at, sizeof(T));
    if (bigEndian != hostIsBigEndian()) std::reverse(bytes, bytes + sizeof(T));
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
}

/// Appends `value` to `out` in little-endian order.
template <typename T, typename Bytes>
void appendLittle(Bytes& out, T value)
{
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (hostIsBigEndian()) std::reverse(bytes, bytes + sizeof(T));
    out.insert(out.end(), bytes, bytes + sizeof(T));
}

}  // namespace sculpt
