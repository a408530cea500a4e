// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file import_preview.h
/// @brief A scan or mesh read once for the window's Import panel: what the file holds, and a
///        coarse preview of the surface the import options give, fast enough to follow a slider.
///
/// The preview converts at a voxel size giving about kPreviewVoxelsAcross voxels along the
/// shape's longest side (never finer than the scan). A scan's crop, smoothing and low-pass
/// filtering for that voxel size are redone only when the crop or the smoothing changes, so
/// moving the iso-value costs one coarse conversion. Apply imports with importShape (the same
/// grid as `sculpt import`), never from the preview.

#include "core/io/mesh_import.h"
#include "core/scan/scan_volume.h"
#include "sculpt/session/shape_import.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace sculpt {

class ImportPreview {
public:
    static constexpr double kPreviewVoxelsAcross = 96.0;
    static constexpr int kHistogramBins = 256;

    /// Reads `path` as importShape would (a scan file, a DICOM directory or a mesh).
    /// @throws InputError naming the file and what is wrong with it.
    explicit ImportPreview(const std::filesystem::path& path);

    const std::filesystem::path& path() const { return mPath; }
    bool isScan() const { return mScan.has_value(); }
    /// Scans only: the samples as read.
    const ScanVolume& scan() const { return *mScan; }
    /// Scans only: whether the samples take two values only (a mask: ScanVolume::twoValued).
    bool twoValued() const { return mTwoValued; }
    /// Scans only: a label map's labels (ScanVolume::labels), empty for intensities.
    const std::vector<int>& labels() const { return mLabels; }
    /// Scans only: a segmentation of two labels or more besides the background (not an
    /// intensity scan of few values: kLeastLabelMapAgreement).
    bool labelMap() const { return mLabelMap; }
    /// Meshes only: its triangles and open or non-manifold edges.
    const MeshImportReport& meshReport() const { return mMeshReport; }
    /// What importShape uses without a voxel size: the scan's smallest spacing, or the mesh's
    /// longest side / 256.
    double defaultVoxelSize() const { return mDefaultVoxelSize; }
    double previewVoxelSize() const { return mPreviewVoxelSize; }

    /// Scans: the histogram (kHistogramBins bins over the range) and Otsu's threshold of the
    /// samples the options keep (cropped, smoothed): what an import without an iso-value uses.
    /// @throws InputError for a crop outside the scan.
    const std::vector<double>& histogram(const ImportOptions& options);
    double otsuThreshold(const ImportOptions& options);
    /// Scans: the value range of those samples.
    std::pair<double, double> range(const ImportOptions& options);

    /// The surface the options give, at the preview's voxel size (the largest component only, if
    /// asked). @throws InputError as importShape (an iso-value outside the samples, nothing inside).
    FieldImage surface(const ImportOptions& options);

private:
    /// The crop, label and smoothing of `options` applied, if they differ from the last ones.
    void prepare(const ImportOptions& options);

    std::filesystem::path mPath;
    std::optional<ScanVolume> mScan;
    std::optional<TriangleMesh> mMesh;
    MeshImportReport mMeshReport;
    double mDefaultVoxelSize = 0.0, mPreviewVoxelSize = 0.0;
    bool mTwoValued = false;
    std::vector<int> mLabels;
    bool mLabelMap = false;
    // The scan as the last options prepared it.
    struct Prepared {
        std::optional<openvdb::CoordBBox> crop;
        std::optional<int> label;
        double smoothSigma = -1.0;
        std::optional<ScanVolume> kept;      // cropped, one label's mask, smoothed: what Otsu and the histogram read
        std::optional<ScanVolume> filtered;  // kept, low-pass filtered for the preview's voxel size
        std::vector<double> histogram;
        double otsu = 0.0;
    };
    Prepared mPrepared;
};

}  // namespace sculpt
