// SPDX-License-Identifier: Apache-2.0
#include "core/io/vdb_tree_check.h"

#include <openvdb/io/Compression.h>
#include <openvdb/math/Maps.h>
#include <openvdb/openvdb.h>

#include <bitset>
#include <cstring>
#include <set>
#include <sstream>
#include <tuple>
#include <vector>

namespace sculpt {

namespace {

namespace io = openvdb::io;

// Tree_float_5_4_3: log2 of the node widths, top to bottom.
constexpr int kUpperLog2 = 5, kLowerLog2 = 4, kLeafLog2 = 3;
constexpr std::int32_t kTopNodeWidth = 1 << (kUpperLog2 + kLowerLog2 + kLeafLog2);

/// A node's child or value mask: one bit per entry, as OpenVDB stores it.
class NodeMask {
public:
    NodeMask(BoundedReader& in, int log2Dim, const char* what)
        : mBytes(in.readBytes((std::int64_t(1) << (3 * log2Dim)) / 8, what))
    {}

    std::size_t entries() const { return mBytes.size() * 8; }
    bool isOn(std::size_t i) const { return (std::uint8_t(mBytes[i / 8]) >> (i % 8)) & 1; }
    bool overlaps(const NodeMask& other) const
    {
        for (std::size_t i = 0; i < mBytes.size(); ++i) {
            if (mBytes[i] & other.mBytes[i]) return true;
        }
        return false;
    }
    std::size_t countOn() const
    {
        std::size_t on = 0;
        for (const char byte : mBytes) on += std::bitset<8>(std::uint8_t(byte)).count();
        return on;
    }

private:
    std::string mBytes;
};

class TreeWalk {
public:
    TreeWalk(BoundedReader& in, const VdbValueCoding& coding) : mIn(in), mCoding(coding) {}

    void transform()
    {
        const std::string type = mIn.readString("the grid's transform");
        if (!openvdb::math::MapRegistry::isRegistered(type))
            throw InputError("corrupt (unknown transform type '" + type.substr(0, 40) + "')");
        if (type == openvdb::math::NonlinearFrustumMap::mapType())
            throw InputError("the grid has a frustum transform; a distance field needs a linear one");
        openvdb::math::MapRegistry::createMap(type)->read(mIn.stream());  // fixed-size fields
    }

    void topology()
    {
        mIn.read<std::int32_t>("the tree's buffer count");
        mIn.read<float>("the tree's background");
        const auto tiles = mIn.read<std::uint32_t>("the tree's tile count");
        const auto children = mIn.read<std::uint32_t>("the tree's node count");
        // A tile takes 17 bytes, a node at least 12 plus its two masks.
        const std::int64_t smallest = 17 * std::int64_t(tiles) + (12 + 8192) * std::int64_t(children);
        if (smallest > mIn.remaining()) throw InputError("corrupt (more top-level tiles and nodes than bytes)");
        std::set<std::tuple<std::int32_t, std::int32_t, std::int32_t>> origins;
        for (std::uint32_t i = 0; i < tiles; ++i) {
            topLevelOrigin(origins, /*isNode=*/false);
            mIn.read<float>("a tile value");
            if (mIn.read<std::uint8_t>("a tile's state") > 1)
                throw InputError("corrupt (a tile's state is not 0 or 1)");
        }
        for (std::uint32_t i = 0; i < children; ++i) {
            topLevelOrigin(origins, /*isNode=*/true);
            internalNode(kUpperLog2);
        }
    }

    /// The leaves' values: each chunk's lengths, not its bytes (decoding every leaf twice would
    /// double a load; a chunk whose lengths agree is one OpenVDB decodes or refuses).
    void buffers()
    {
        for (std::int64_t i = 0; i < mLeaves; ++i) {
            const NodeMask valueMask(mIn, kLeafLog2, "a leaf's value mask");
            values(valueMask, "a leaf's values", /*decode=*/false);
        }
    }

private:
    /// Top-level entries sit on node boundaries, each once: OpenVDB keys them by the stored
    /// origin, so a repeated node would replace (and leak) the one before it.
    void topLevelOrigin(std::set<std::tuple<std::int32_t, std::int32_t, std::int32_t>>& seen, bool isNode)
    {
        std::int32_t xyz[3];
        for (std::int32_t& c : xyz) {
            c = mIn.read<std::int32_t>("a top-level origin");
            if (c % kTopNodeWidth != 0) throw InputError("corrupt (a top-level tile or node is off its grid)");
        }
        if (!seen.emplace(xyz[0], xyz[1], xyz[2]).second && isNode)
            throw InputError("corrupt (two top-level nodes at one origin)");
    }

    void internalNode(int log2Dim)
    {
        const NodeMask childMask(mIn, log2Dim, "a node's child mask");
        const NodeMask valueMask(mIn, log2Dim, "a node's value mask");
        // OpenVDB keeps an entry's child bit and value bit exclusive and trusts that it does.
        if (childMask.overlaps(valueMask)) throw InputError("corrupt (a node entry is both a child and a value)");
        values(valueMask, "a node's tile values");
        for (std::size_t i = 0; i < childMask.entries(); ++i) {
            if (!childMask.isOn(i)) continue;
            if (log2Dim == kLowerLog2) {
                NodeMask(mIn, kLeafLog2, "a leaf's value mask");
                ++mLeaves;
            } else {
                internalNode(kLowerLog2);
            }
        }
    }

    /// One node's values as io::readCompressedValues reads them (format 222 and later).
    void values(const NodeMask& valueMask, const char* what, bool decode = true)
    {
        const auto metadata = mIn.read<std::int8_t>(what);
        const bool oneInactive = metadata == io::NO_MASK_AND_ONE_INACTIVE_VAL ||
                                 metadata == io::MASK_AND_ONE_INACTIVE_VAL ||
                                 metadata == io::MASK_AND_TWO_INACTIVE_VALS;
        const bool selectionMask = metadata == io::MASK_AND_NO_INACTIVE_VALS ||
                                   metadata == io::MASK_AND_ONE_INACTIVE_VAL ||
                                   metadata == io::MASK_AND_TWO_INACTIVE_VALS;
        if (oneInactive) mIn.skip(sizeof(float), what);
        if (metadata == io::MASK_AND_TWO_INACTIVE_VALS) mIn.skip(sizeof(float), what);
        if (selectionMask) mIn.skip(std::int64_t(valueMask.entries() / 8), what);
        const bool activeOnly =
            (mCoding.compression & io::COMPRESS_ACTIVE_MASK) && metadata != io::NO_MASK_AND_ALL_VALS;
        const std::size_t count = activeOnly ? valueMask.countOn() : valueMask.entries();
        const std::size_t bytes = count * (mCoding.halfFloat ? 2 : sizeof(float));
        if (mCoding.halfFloat && count == 0) return;  // OpenVDB's half writer stores no chunk at all
        if (mCoding.compression & (io::COMPRESS_BLOSC | io::COMPRESS_ZIP)) {
            chunk(bytes, what, decode);
        } else {
            mIn.skip(std::int64_t(bytes), what);
        }
    }

    /// A zip or Blosc chunk: its stored length within the file, and (if `decode`) that it
    /// decodes to exactly `bytes`. OpenVDB allocates the stored length before reading it.
    void chunk(std::size_t bytes, const char* what, bool decode)
    {
        const auto stored = mIn.read<std::int64_t>(what);
        if (stored <= 0) {  // stored raw
            // Negated unsigned: INT64_MIN has no signed negation.
            if (std::uint64_t(0) - std::uint64_t(stored) != bytes)
                throw InputError(std::string("corrupt (") + what + " have the wrong size)");
            mIn.skip(-stored, what);
            return;
        }
        if (stored > mIn.remaining()) throw InputError(std::string("corrupt (") + what + " run past the grid's end)");
        if (!decode) return lengthsOnly(stored, bytes, what);
        const std::string packed = mIn.readBytes(stored, what);
        if (mCoding.compression & io::COMPRESS_BLOSC) checkBloscHeader(packed, packed.size(), bytes, what);
        std::string framed(sizeof stored, '\0');
        std::memcpy(framed.data(), &stored, sizeof stored);
        std::istringstream chunkStream(framed + packed);
        std::vector<char> decoded(bytes);
        try {
            if (mCoding.compression & io::COMPRESS_BLOSC) {
                io::bloscFromStream(chunkStream, decoded.data(), bytes);
            } else {
                io::unzipFromStream(chunkStream, decoded.data(), bytes);
            }
        } catch (const openvdb::Exception&) {
            throw InputError(std::string("corrupt (") + what + " do not decompress)");
        }
    }

    /// A chunk left to OpenVDB: only its Blosc header (16 bytes) is read.
    void lengthsOnly(std::int64_t stored, std::size_t bytes, const char* what)
    {
        if (!(mCoding.compression & io::COMPRESS_BLOSC)) return mIn.skip(stored, what);
        const std::int64_t head = std::min<std::int64_t>(stored, 16);
        checkBloscHeader(mIn.readBytes(head, what), std::size_t(stored), bytes, what);
        mIn.skip(stored - head, what);
    }

    /// Blosc trusts the lengths in its 16-byte header (`packed` starts with it): they must agree
    /// with the chunk's `stored` length and the `bytes` it decodes to.
    static void checkBloscHeader(const std::string& packed, std::size_t stored, std::size_t bytes, const char* what)
    {
        std::uint32_t decodedBytes = 0, packedBytes = 0;
        if (packed.size() >= 16) {
            std::memcpy(&decodedBytes, packed.data() + 4, 4);
            std::memcpy(&packedBytes, packed.data() + 12, 4);
        }
        if (decodedBytes != bytes || packedBytes != stored)
            throw InputError(std::string("corrupt (") + what + " have a damaged Blosc header)");
    }

    BoundedReader& mIn;
    VdbValueCoding mCoding;
    std::int64_t mLeaves = 0;
};

}  // namespace

void checkVdbFloatTree(BoundedReader& in, const VdbValueCoding& coding, bool throughBuffers, std::int64_t topologyEnd)
{
    openvdb::initialize();  // the map registry names the transform types
    TreeWalk walk(in, coding);
    walk.transform();
    walk.topology();
    if (topologyEnd >= 0 && in.position() != topologyEnd)
        throw InputError("corrupt (the topology does not end where the file says)");
    if (throughBuffers) walk.buffers();
}

}  // namespace sculpt
