// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file enum_names.h
/// @brief The names an enumeration is written with in files and messages, in one table per enum.
///
/// A table lists every value with its name, in the order messages list them:
///     constexpr EnumNames<Falloff, 4> kFalloffNames{{{Falloff::Smooth, "smooth"}, ...}};
/// enumFromName reads a name ("falloff", "smooth") and refuses others with the valid ones listed:
///     unknown falloff "soft" (expected smooth, sphere, sharp or constant)

#include "core/base/errors.h"

#include <array>
#include <cstddef>
#include <string>
#include <utility>

namespace sculpt {

template <typename Enum, std::size_t N>
using EnumNames = std::array<std::pair<Enum, const char*>, N>;

/// The value called `name`. @throws InputError naming `what` and listing the valid names.
template <typename Enum, std::size_t N>
Enum enumFromName(const EnumNames<Enum, N>& names, const std::string& name, const char* what)
{
    for (const auto& [value, text] : names) {
        if (name == text) return value;
    }
    std::string valid;
    for (std::size_t i = 0; i < N; ++i) {
        valid += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + names[i].second;
    }
    throw InputError(std::string("unknown ") + what + " \"" + name + "\" (expected " + valid + ")");
}

/// The name of `value`; "?" for a value missing from the table.
template <typename Enum, std::size_t N>
const char* enumName(const EnumNames<Enum, N>& names, Enum value)
{
    for (const auto& [candidate, text] : names) {
        if (candidate == value) return text;
    }
    return "?";
}

}  // namespace sculpt
