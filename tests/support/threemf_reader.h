// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file threemf_reader.h
/// @brief A 3MF file as lib3mf (Debian's lib3mf-dev, the 3MF Consortium's library) reads it: the
///        independent reader our 3MF writer is checked against.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sculpt::test {

struct ThreeMfModel {
    struct Object {
        std::string name;
        std::size_t vertices = 0, triangles = 0;
        std::array<std::uint8_t, 3> colour{};  ///< its base material's display colour
        double minZ = 0.0, maxZ = 0.0;         ///< its extent along z
    };
    bool read = false;  ///< lib3mf read the file without an error
    int unit = -1;      ///< lib3mf's eModelUnit: 1 is millimetres
    std::vector<Object> objects;
    std::size_t buildItems = 0;
};

ThreeMfModel readThreeMf(const std::filesystem::path& path);

}  // namespace sculpt::test
