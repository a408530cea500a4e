// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file triangle_mesh.h
/// @brief An indexed triangle mesh in world coordinates: what meshers produce and writers save.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace sculpt {

/// An allocator whose resize() leaves new elements uninitialised: meshes of millions of vertices
/// are then filled in parallel (first touch on every core) instead of zeroed by one thread.
template <typename T>
struct UninitialisedAllocator : std::allocator<T> {
    template <typename U>
    struct rebind {
        using other = UninitialisedAllocator<U>;
    };
    UninitialisedAllocator() = default;
    template <typename U>
    UninitialisedAllocator(const UninitialisedAllocator<U>&)
    {}
    template <typename U>
    void construct(U* p)
    {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args)
    {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

template <typename T>
using MeshArray = std::vector<T, UninitialisedAllocator<T>>;

struct TriangleMesh {
    /// #V world-space positions.
    MeshArray<std::array<float, 3>> positions;
    /// #V unit normals pointing outwards (towards positive distance), or empty.
    MeshArray<std::array<float, 3>> normals;
    /// #F triangles as indices into positions, counter-clockwise seen from outside.
    MeshArray<std::array<std::uint32_t, 3>> triangles;

    /// Every position a finite number (what a writer may write).
    bool finite() const
    {
        return std::all_of(positions.begin(), positions.end(), [](const std::array<float, 3>& p) {
            return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
        });
    }
};

}  // namespace sculpt
