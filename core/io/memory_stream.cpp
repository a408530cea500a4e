// SPDX-License-Identifier: Apache-2.0
#include "core/io/memory_stream.h"

namespace sculpt {

MemoryStream::Buffer::Buffer(const char* first, const char* last, std::int64_t base) : mBase(base)
{
    char* begin = const_cast<char*>(first);  // never written: an input buffer only
    setg(begin, begin, begin + (last - first));
}

MemoryStream::Buffer::pos_type MemoryStream::Buffer::seekoff(off_type offset, std::ios::seekdir dir, std::ios::openmode)
{
    const std::int64_t size = egptr() - eback();
    const std::int64_t from = dir == std::ios::beg ? -mBase : dir == std::ios::cur ? gptr() - eback() : size;
    const std::int64_t at = from + offset;  // an index into the bytes
    if (at < 0 || at > size) return pos_type(off_type(-1));
    setg(eback(), eback() + at, egptr());
    return pos_type(off_type(mBase + at));
}

MemoryStream::Buffer::pos_type MemoryStream::Buffer::seekpos(pos_type position, std::ios::openmode mode)
{
    return seekoff(off_type(position), std::ios::beg, mode);
}

MemoryStream::MemoryStream(const char* first, const char* last, std::int64_t base)
    : std::istream(nullptr), mBuffer(first, last, base)
{
    rdbuf(&mBuffer);
}

}  // namespace sculpt
