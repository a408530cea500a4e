#include "json_fields.h"

#include "errors.h"

#include <cmath>

namespace sculpt::json_fields {

using nlohmann::json;

const json& field(const json& object, const char* key, const std::string& where)
{
    if (!object.is_object() || !object.contains(key)) throw InputError(where + ": missing field '" + key + "'");
    return object.at(key);
}

double number(const json& object, const char* key, const std::string& where)
{
    const json& value = field(object, key, where);
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
        throw InputError(where + ": field '" + key + "' must be a finite number");
    }
    return value.get<double>();
}

double numberOr(const json& object, const char* key, double fallback, const std::string& where)
{
    return object.contains(key) ? number(object, key, where) : fallback;
}

std::string textOr(const json& object, const char* key, const std::string& fallback, const std::string& where)
{
    if (!object.contains(key)) return fallback;
    const json& value = object.at(key);
    if (!value.is_string()) throw InputError(where + ": field '" + key + "' must be a string");
    return value.get<std::string>();
}

bool flagOr(const json& object, const char* key, bool fallback, const std::string& where)
{
    if (!object.contains(key)) return fallback;
    const json& value = object.at(key);
    if (!value.is_boolean()) throw InputError(where + ": field '" + key + "' must be true or false");
    return value.get<bool>();
}

openvdb::Vec3d vec3(const json& value, const std::string& what)
{
    const std::string message = what + " must be an array of 3 finite numbers";
    if (!value.is_array() || value.size() != 3) throw InputError(message);
    openvdb::Vec3d v;
    for (int i = 0; i < 3; ++i) {
        const json& element = value[size_t(i)];
        if (!element.is_number() || !std::isfinite(element.get<double>())) throw InputError(message);
        v[i] = element.get<double>();
    }
    return v;
}

json parse(const std::string& text, const std::string& source)
{
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError(source + ": malformed JSON (" + e.what() + ")");
    }
}

} // namespace sculpt::json_fields
