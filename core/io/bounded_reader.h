// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file bounded_reader.h
/// @brief Reads little-endian fields from a stream of known size, refusing any length or count
///        that runs past its end before anything is allocated for it.

#include "core/base/errors.h"

#include <cstdint>
#include <istream>
#include <string>

namespace sculpt {

class BoundedReader {
public:
    /// `in` must throw on short reads; `size` is where its bytes end.
    BoundedReader(std::istream& in, std::int64_t size) : mIn(in), mSize(size) {}

    std::istream& stream() { return mIn; }
    std::int64_t size() const { return mSize; }
    std::int64_t position() { return std::int64_t(mIn.tellg()); }
    std::int64_t remaining() { return mSize - position(); }

    template <typename T>
    T read(const char* what)
    {
        need(sizeof(T), what);
        T value;
        mIn.read(reinterpret_cast<char*>(&value), sizeof(T));
        return value;
    }

    std::string readBytes(std::int64_t length, const char* what)
    {
        need(length, what);
        std::string bytes(std::size_t(length), '\0');
        mIn.read(bytes.data(), std::streamsize(length));
        return bytes;
    }

    std::string readString(const char* what) { return readBytes(read<std::uint32_t>(what), what); }

    void skip(std::int64_t bytes, const char* what)
    {
        need(bytes, what);
        mIn.seekg(bytes, std::ios::cur);
    }

    void seek(std::int64_t at, const char* what)
    {
        if (at < position() || at > mSize)
            throw InputError(std::string("corrupt (") + what + " points outside the file)");
        mIn.seekg(at);
    }

    /// Refuses `bytes` more than remain.
    void need(std::int64_t bytes, const char* what)
    {
        const std::int64_t left = remaining();
        if (bytes < 0 || bytes > left) {
            throw InputError(std::string("truncated or corrupt (") + what + " needs " + std::to_string(bytes) +
                             " bytes, " + std::to_string(left) + " remain)");
        }
    }

private:
    std::istream& mIn;
    std::int64_t mSize;
};

}  // namespace sculpt
