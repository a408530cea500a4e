// SPDX-License-Identifier: Apache-2.0
#include "core/io/metadata_seal.h"

#include "core/base/errors.h"

#include <cstdint>
#include <cstdio>
#include <map>
#include <sstream>

namespace sculpt {

namespace {

constexpr const char* kOurs = "sculpt.";

bool ours(const std::string& key) { return key.rfind(kOurs, 0) == 0 && key != kMetadataSealKey; }

/// FNV-1a over the field's name, type and value as OpenVDB writes it (exact for every type).
std::string fieldHash(const std::string& key, const openvdb::Metadata& value)
{
    std::ostringstream bytes;
    value.write(bytes);
    std::uint64_t hash = 14695981039346656037ull;
    for (const std::string& part : {key, value.typeName(), bytes.str()})
        for (const unsigned char c : part) hash = (hash ^ c) * 1099511628211ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

/// The `sculpt.*` fields of `meta` and their hashes.
std::map<std::string, std::string> fieldHashes(const openvdb::MetaMap& meta)
{
    std::map<std::string, std::string> hashes;
    for (auto it = meta.beginMeta(); it != meta.endMeta(); ++it)
        if (ours(it->first)) hashes[it->first] = fieldHash(it->first, *it->second);
    return hashes;
}

}  // namespace

void sealMetadata(openvdb::MetaMap& meta)
{
    meta.removeMeta(kMetadataSealKey);
    std::string seal;
    for (const auto& [key, hash] : fieldHashes(meta)) seal += key + "=" + hash + ";";
    meta.insertMeta(kMetadataSealKey, openvdb::StringMetadata(seal));
}

void checkMetadataSeal(const openvdb::MetaMap& meta, const std::string& whose)
{
    const auto sealed = meta.getMetadata<openvdb::StringMetadata>(kMetadataSealKey);
    if (!sealed) return;
    std::map<std::string, std::string> expected;
    std::istringstream entries(sealed->value());
    for (std::string entry; std::getline(entries, entry, ';');) {
        const auto equals = entry.find('=');
        if (equals == std::string::npos) throw InputError(whose + ": its metadata seal is damaged");
        expected[entry.substr(0, equals)] = entry.substr(equals + 1);
    }
    const std::map<std::string, std::string> found = fieldHashes(meta);
    for (const auto& [key, hash] : expected) {
        const auto it = found.find(key);
        if (it == found.end())
            throw InputError(whose + ": its field '" + key + "' was removed after it was written (damaged or edited)");
        if (it->second != hash)
            throw InputError(whose + ": its field '" + key + "' was changed after it was written (damaged or edited)");
    }
    for (const auto& [key, hash] : found)
        if (!expected.count(key))
            throw InputError(whose + ": its field '" + key + "' was added after it was written (damaged or edited)");
}

}  // namespace sculpt
