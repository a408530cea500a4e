// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file vdb_tree_check.h
/// @brief Walks a float grid's transform and tree in a `.vdb` file the way OpenVDB's reader
///        will, checking every origin, mask, count and compressed chunk first.
///
/// OpenVDB's `RootNode::readTopology` allocates each top-level node with a raw `new` and
/// inserts it only once its subtree has been read: a throw in between leaks the subtree, and a
/// throw inside a nested node makes its destructor delete tile values as child pointers. A
/// chunk whose stored length disagrees with its node overruns OpenVDB's buffers, and one that
/// claims more bytes than the file holds is allocated whole before a byte of it is read. A tree that
/// passes this walk is one OpenVDB reads without throwing.

#include "core/io/bounded_reader.h"

#include <cstdint>

namespace sculpt {

/// How a grid's values are stored: from the grid's compression flags and its type name.
struct VdbValueCoding {
    std::uint32_t compression = 0;  ///< OpenVDB's COMPRESS_* flags
    bool halfFloat = false;         ///< saved as 16-bit floats
};

/// Checks a `Tree_float_5_4_3` grid from its transform on (where `in` stands) through its
/// topology, which must end at `topologyEnd` unless that is -1 (a file without grid offsets),
/// and, with `throughBuffers`, every leaf's values (their chunks' lengths); leaves `in` where
/// the walk ended. @throws InputError (not naming the file) saying what is wrong.
void checkVdbFloatTree(BoundedReader& in, const VdbValueCoding& coding, bool throughBuffers,
                       std::int64_t topologyEnd = -1);

}  // namespace sculpt
