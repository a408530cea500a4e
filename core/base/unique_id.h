// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file unique_id.h
/// @brief An identity that is never handed out twice in a process: what a viewer keys its cache
///        on (with a version), where an address can be freed and handed back to a new object.

#include <atomic>
#include <cstdint>

namespace sculpt {

class UniqueId {
public:
    UniqueId() : mValue(next()) {}
    /// A copy, or an object moved into, is another object: it gets an identity of its own.
    UniqueId(const UniqueId&) : UniqueId() {}
    UniqueId& operator=(const UniqueId&)
    {
        mValue = next();
        return *this;
    }

    std::uint64_t value() const { return mValue; }

private:
    static std::uint64_t next()
    {
        static std::atomic<std::uint64_t> counter{0};
        return ++counter;
    }
    std::uint64_t mValue;
};

}  // namespace sculpt
