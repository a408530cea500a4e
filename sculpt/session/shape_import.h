// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file shape_import.h
/// @brief Any shape a user brings — a document, a scan, a mesh — as a field image.

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/field/piece.h"
#include "core/scan/largest_component.h"
#include "core/scan/scan_readers.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sculpt {

struct ImportOptions {
    std::optional<double> iso;  ///< scans: the surface's value; Otsu's threshold if unset
    /// scans of labels (a segmentation): the surface around the samples of this label, as a
    /// mask (ScanVolume::labelMask) split at 0.5; excludes iso.
    std::optional<int> label;
    std::optional<double> voxelSize;         ///< scans: native (smallest spacing); meshes: longest side / 256
    std::optional<openvdb::CoordBBox> crop;  ///< scans: sample index box, inclusive
    double smoothSigma = 0.0;                ///< scans: Gaussian pre-smoothing, world units (0: none)
    bool largestComponent = false;           ///< keep only the largest solid piece, cavities filled
    /// scans: anti-alias the surface's voxel terraces (surface_flows.h antiAlias); unset: for
    /// scans whose samples take two values only (a mask), whose surface is all terraces.
    std::optional<bool> antiAliasMask;
    std::optional<RawLayout> raw;  ///< read the input as raw samples with this layout
    /// scans: keep the samples read (cropped) for the document (ImportReport::keptScan).
    bool keepScan = false;
};

/// The iso-value a scan imports at: the options', a label mask's middle (0.5), else `otsu()`.
double scanIso(const ImportOptions& options, const std::function<double()>& otsu);
/// Whether a scan's surface is anti-aliased: as the options say, else for masks (two-valued
/// samples, `twoValued`) and labels.
bool antiAliasesMask(const ImportOptions& options, bool twoValued);

/// What an import did, for the user.
struct ImportReport {
    std::string kind;  ///< "scan" or "mesh"
    double iso = 0.0;
    bool isoChosen = false;  ///< by Otsu
    double voxelSize = 0.0;
    bool antiAliased = false;       ///< scans: low-pass filtered for a voxel size coarser than the scan's
    LargestComponentReport pieces;  ///< with largestComponent
    bool twoValued = false;         ///< scans: the samples take two values only (a mask)
    bool maskAntiAliased = false;   ///< scans: the terraces were anti-aliased
    /// Closed meshes whose topology the voxel size changed: a finer one that keeps it, if found.
    std::optional<double> topologyKeepingVoxelSize;
    std::vector<std::string> warnings;
    /// scans, with keepScan: the samples as a grid for the document (kept_scan.h).
    openvdb::FloatGrid::Ptr keptScan;
};

/// Imports a scan (readScan, or raw), or a mesh (.obj, .ply, .stl, .off).
/// @throws InputError naming the file and the problem: e.g. an iso-value outside the data, an
///         empty result, scan options given for a mesh.
FieldImage importShape(const std::filesystem::path& input, const ImportOptions& options, ImportReport& report,
                       const Progress& progress = {});

/// The label every segmentation tool gives the samples outside all structures.
constexpr int kBackgroundLabel = 0;
/// Below this ScanVolume::sameNeighbourFraction() a scan of few integer values is taken for
/// intensities, not labels (ScanVolume's figures).
constexpr double kLeastLabelMapAgreement = 0.5;

/// Imports a label map (a segmentation: integer samples, one value per structure) as one piece
/// per label but the background, named "label N": each label's surface as `label` imports it,
/// from the samples around it only. `report` tells of the last piece and every warning.
/// @throws InputError naming the file if it is a mesh, its samples are not labels, or it holds
///         background only; as importShape otherwise.
std::vector<Piece> importLabelPieces(const std::filesystem::path& input, const ImportOptions& options,
                                     ImportReport& report, const Progress& progress = {});

/// A document (.vdb) as is, or anything importShape reads with its defaults (and the given voxel
/// size, so two shapes can share a lattice); warnings go to `warnings`.
FieldImage loadShape(const std::filesystem::path& input, std::optional<double> voxelSize,
                     std::vector<std::string>& warnings, const Progress& progress = {});

}  // namespace sculpt
