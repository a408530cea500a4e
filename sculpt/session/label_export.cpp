// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/label_export.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/scan/kept_scan.h"
#include "core/scan/label_map_files.h"
#include "core/scan/scan_readers.h"

namespace sculpt {

ScanLattice labelLattice(const std::filesystem::path& like, const openvdb::FloatGrid::ConstPtr& keptScan,
                         const std::string& document)
{
    if (!like.empty()) return readScan(like).lattice();
    if (!keptScan) {
        throw InputError(document +
                         ": keeps no scan to label (imported with --no-keep-scan, or not from a scan); name the "
                         "scan the labels are for (--like SCAN)");
    }
    try {
        return keptScanRecord(*keptScan).lattice;
    } catch (const InputError& e) {
        throw InputError(document + ": " + e.what());
    }
}

LabelMap exportLabels(const std::vector<Piece>& pieces, const ScanLattice& lattice, const std::filesystem::path& output,
                      const Progress& progress)
{
    checkLabelMapPath(output);
    AtomicFile::checkTarget(output);
    LabelMap map = labelMapOf(pieces, lattice, scaledProgress(progress, 0.0, 0.8));
    writeLabelMap(map, output);
    report(progress, 1.0);
    return map;
}

std::vector<std::string> describeLabels(const LabelMap& map)
{
    const openvdb::Coord& d = map.lattice.dims;
    std::vector<std::string> lines{std::to_string(map.segments.size()) + " labels on " + std::to_string(d.x()) + " x " +
                                   std::to_string(d.y()) + " x " + std::to_string(d.z()) + " samples:"};
    for (const LabelSegment& segment : map.segments) {
        lines.push_back(std::to_string(segment.label) + " '" + segment.name + "': " +
                        (segment.samples ? std::to_string(segment.samples) + " samples"
                                         : std::string("no sample (the piece lies off the lattice or is thinner "
                                                       "than its samples)")));
    }
    return lines;
}

}  // namespace sculpt
