// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file json_fields.h
/// @brief Reading typed fields from JSON documents with messages that say where and what.
///
/// `where` names the place for messages ("scene.json: primitive 2 ('head')"); every error is an
/// InputError "<where>: field '<key>' must be ...".

#include <nlohmann/json.hpp>
#include <openvdb/openvdb.h>

#include <initializer_list>
#include <string>

namespace sculpt::json_fields {

/// The field, or InputError if `object` is not an object or lacks it.
const nlohmann::json& field(const nlohmann::json& object, const char* key, const std::string& where);
/// A finite number.
double number(const nlohmann::json& object, const char* key, const std::string& where);
/// number(), or `fallback` if the field is absent.
double numberOr(const nlohmann::json& object, const char* key, double fallback, const std::string& where);
/// A string, or `fallback` if absent.
std::string textOr(const nlohmann::json& object, const char* key, const std::string& fallback,
                   const std::string& where);
/// A boolean, or `fallback` if absent.
bool flagOr(const nlohmann::json& object, const char* key, bool fallback, const std::string& where);
/// An array of 3 finite numbers; `what` names it in messages.
openvdb::Vec3d vec3(const nlohmann::json& value, const std::string& what);
/// InputError naming the first field of `object` not in `allowed` (a typo would otherwise be
/// silently ignored).
void onlyFields(const nlohmann::json& object, std::initializer_list<const char*> allowed, const std::string& where);
/// Parses text, or InputError "<source>: malformed JSON (...)".
nlohmann::json parse(const std::string& text, const std::string& source);

}  // namespace sculpt::json_fields
