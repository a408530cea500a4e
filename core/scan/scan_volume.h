// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scan_volume.h
/// @brief A medical volume (CT, MRI) as read from its file: samples on a lattice and the lattice's
///        place in the world.
///
/// Made by the readers (scan_readers.h). The samples stay in the file's type (an 8-bit scan costs one byte per voxel) and are read a
/// slice or a few points at a time as floats, so converting a scan never needs a float copy of
/// all of it.

#include "core/scan/scan_lattice.h"

#include <openvdb/openvdb.h>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace sculpt {

struct ChildReply;

class ScanVolume {
public:
    struct Impl;
    explicit ScanVolume(std::shared_ptr<const Impl> impl);
    /// The image behind it, for the code of scan/ that includes vtk_image_scan.h.
    const Impl& impl() const { return *mImpl; }

    /// Samples along x, y, z.
    openvdb::Coord dims() const;
    /// Maps a sample's index (i, j, k) to its world position: spacing, orientation, origin.
    const openvdb::Mat4d& worldFromIndex() const;
    /// dims() and worldFromIndex().
    ScanLattice lattice() const { return {dims(), worldFromIndex()}; }
    /// Longest side of the box the samples span in the world.
    double worldExtent() const;
    /// World distance between neighbouring samples along index axis 0, 1 or 2.
    double spacing(int axis) const;
    /// Smallest and largest sample.
    std::pair<double, double> range() const;
    /// Bytes of the samples in their file type.
    std::size_t denseBytes() const;
    /// The file or directory it came from, for messages.
    const std::string& source() const;
    /// What reading it noticed and worked around (a DICOM series' uneven slice spacing), for the user.
    const std::vector<std::string>& warnings() const;

    /// Copies slice k (dims.x * dims.y samples, x fastest) into `out` as floats.
    void readSlice(int k, float* out) const;
    /// Trilinear samples at points given in index space (i, j, k); `outside` for points off the
    /// lattice. Thread-safe.
    void sample(const openvdb::Vec3d* points, std::size_t count, float outside, float* out) const;

    /// The samples of an index box (inclusive), placed where they were.
    /// @throws InputError if the box does not overlap the scan.
    ScanVolume cropped(const openvdb::CoordBBox& box) const;
    /// Gaussian-smoothed samples (standard deviation in world units, per axis in voxels).
    ScanVolume smoothed(double sigmaWorld) const;
    /// The samples low-pass filtered for resampling at a coarser voxel size, so that noise and
    /// detail finer than a voxel average out instead of aliasing into a rough surface: along each
    /// axis with spacing s < h, a Gaussian of sigma sqrt(h^2 - s^2) / 2 (world units). Nothing
    /// (nullopt) if no axis is finer than h by enough to matter.
    std::optional<ScanVolume> antiAliased(double voxelSizeWorld) const;
    /// Sample counts in `bins` equal bins spanning range().
    std::vector<double> histogram(int bins) const;
    /// Whether every sample is the smallest or the largest value (and they differ): a mask,
    /// whose surface at any iso-value between them is all voxel terraces.
    bool twoValued() const;
    /// The values of a label map, ascending: every distinct sample value, when all are integers
    /// and there are at most kMaxLabels of them; empty otherwise (intensities, not labels).
    std::vector<int> labels() const;
    static constexpr std::size_t kMaxLabels = 4096;
    /// Among the pairs of neighbouring samples along x that are not both 0, the fraction holding
    /// one value: most of a label map's (regions of one label; 0.68 to 0.89 in MRIcron's atlases),
    /// few of an intensity scan's, even one of few values (noise; 0.09 to 0.23 for its MRIs).
    double sameNeighbourFraction() const;
    /// Where each value of a label map (labels()) lies: the index box of its samples, and their count.
    struct LabelExtent {
        openvdb::CoordBBox box;
        std::size_t samples = 0;
    };
    std::map<int, LabelExtent> labelExtents() const;
    /// A mask of one label: 1 where the sample is `label`, 0 elsewhere (bytes), placed as the scan.
    ScanVolume labelMask(int label) const;
    /// Otsu's threshold: the value that best splits a 256-bin histogram into two classes.
    double otsuThreshold() const;

private:
    friend ChildReply packScan(const ScanVolume& scan);  // scan_transfer.h
    static constexpr double kMinSigmaVoxels = 0.25;      // below, the filter would change nothing visible
    ScanVolume gaussian(const openvdb::Vec3d& sigmaVoxels) const;
    /// The sample values, ascending; nothing once there are more than `most`.
    std::optional<std::set<double>> distinctValues(std::size_t most) const;

    std::shared_ptr<const Impl> mImpl;
};

}  // namespace sculpt
