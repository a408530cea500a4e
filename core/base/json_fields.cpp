// SPDX-License-Identifier: Apache-2.0
#include "core/base/json_fields.h"

#include "core/base/errors.h"

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

void onlyFields(const json& object, std::initializer_list<const char*> allowed, const std::string& where)
{
    for (const auto& item : object.items()) {
        bool known = false;
        for (const char* name : allowed) known = known || item.key() == name;
        if (known) continue;
        std::string list;
        for (const char* name : allowed) list += std::string(list.empty() ? "" : ", ") + name;
        throw InputError(where + ": unknown field '" + item.key() + "' (expected " + list + ")");
    }
}

namespace {

/// Follows where a SAX parse is (events[3].samples[0][1]) to say where malformed JSON fails.
class PathTracker : public nlohmann::json_sax<json> {
public:
    std::string path() const
    {
        std::string text;
        for (const Level& level : mStack) {
            if (level.array) text += "[" + std::to_string(level.index) + "]";
            else if (!level.key.empty()) text += (text.empty() ? "" : ".") + level.key;
        }
        return text;
    }
    const std::string& error() const { return mError; }

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool key(string_t& key) override
    {
        mStack.back().key = key;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override
    {
        mError = e.what();
        return false;
    }

private:
    struct Level {
        bool array;
        std::size_t index = 0;
        std::string key;
    };
    bool value()
    {
        if (!mStack.empty() && mStack.back().array) ++mStack.back().index;
        return true;
    }
    bool open(bool array)
    {
        mStack.push_back({array, 0, {}});
        return true;
    }
    bool close()
    {
        mStack.pop_back();
        return value();
    }
    std::vector<Level> mStack;
    std::string mError;
};

}  // namespace

json parse(const std::string& text, const std::string& source)
{
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        PathTracker tracker;
        json::sax_parse(text, &tracker);
        const std::string where = tracker.path();
        throw InputError(source + ": malformed JSON" + (where.empty() ? "" : " at " + where) + " (" +
                         (tracker.error().empty() ? e.what() : tracker.error()) + ")");
    }
}

}  // namespace sculpt::json_fields
