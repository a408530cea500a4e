// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file grid_checksum.h
/// @brief A 64-bit fingerprint of a grid's values and active topology.
///
/// Two grids with the same checksum hold, with overwhelming probability, bit-identical values
/// and identical active masks. Documents store it so a damaged file is caught on load; tests
/// use it to prove undo and replays are bit-exact.

#include <openvdb/openvdb.h>

#include <cstdint>
#include <string>

namespace sculpt {

/// Hashes background, every tile (level, origin, value, state) and every leaf (origin, value
/// mask, raw values) in tree order. Deterministic; linear in the number of leaves, parallel.
std::uint64_t gridChecksum(const openvdb::FloatGrid& grid);

/// The checksum as documents store it and `sculpt info` prints it: lower-case hex.
std::string formatChecksum(std::uint64_t checksum);

}  // namespace sculpt
