// SPDX-License-Identifier: Apache-2.0
// Importing a scan into a document beside VTK's vtkFlyingEdges3D on the same volume, in one run:
// wall time and peak memory (peak resident set growth, reset before each iteration through
// /proc/self/clear_refs), and the ratio of that peak to the scan's dense size. Memory counters
// are the median over the iterations: the first one also pays for faulting in library code.
// malloc returns freed blocks to the system (fixed mmap threshold, malloc_trim before each
// iteration), so every iteration allocates afresh.
// Run: build/tests/bench/import_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
//
// BM_ImportScan/0       : ch2bet.nii.gz (mricron-data) read, converted at its native voxel size
//                         (iso 60), written to a .vdb
// BM_FlyingEdges/0      : vtkNIFTIImageReader + vtkFlyingEdges3D at iso 60
// BM_ImportScan/1, BM_FlyingEdges/1 : the same for a synthetic 512^3 uint8 scan of a ball
//                         (raw file, written once to the temporary directory)

#include "core/io/vdb_file.h"
#include "core/scan/scan_readers.h"
#include "core/scan/scan_to_level_set.h"

#include <malloc.h>

#include <benchmark/benchmark.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageReader2.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace sculpt;
namespace fs = std::filesystem;

const char* kMri = "/usr/share/mricron/templates/ch2bet.nii.gz";
constexpr int kSynthetic = 512;
constexpr double kMriIso = 60.0, kBallIso = 100.0;

/// A kSynthetic^3 uint8 ball (radius 200 voxels, ramp across the surface), written once.
fs::path syntheticScan()
{
    const fs::path path = fs::temp_directory_path() / "sculpt_bench_ball512.raw";
    if (fs::exists(path) && fs::file_size(path) == std::uintmax_t(kSynthetic) * kSynthetic * kSynthetic) return path;
    std::ofstream out(path, std::ios::binary);
    std::vector<unsigned char> row(kSynthetic);
    const double c = 0.5 * (kSynthetic - 1);
    for (int z = 0; z < kSynthetic; ++z) {
        for (int y = 0; y < kSynthetic; ++y) {
            for (int x = 0; x < kSynthetic; ++x) {
                const double d = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c)) - 200.0;
                row[size_t(x)] = (unsigned char)(std::clamp(100.0 - 40.0 * d, 0.0, 200.0));
            }
            out.write(reinterpret_cast<const char*>(row.data()), kSynthetic);
        }
    }
    return path;
}

RawLayout syntheticLayout()
{
    RawLayout layout;
    layout.dims = openvdb::Coord(kSynthetic);
    return layout;
}

std::size_t statusKiB(const char* key)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind(key, 0) == 0) return std::stoul(line.substr(std::string(key).size()));
    }
    return 0;
}

// Without it glibc raises its mmap threshold to the largest block freed, and keeps later ones.
const bool kFixedMmapThreshold = mallopt(M_MMAP_THRESHOLD, 128 * 1024) == 1;

/// Peak resident memory above the resident memory at construction, in bytes.
class PeakMemory {
public:
    PeakMemory()
    {
        malloc_trim(0);
        std::ofstream("/proc/self/clear_refs") << "5";  // resets VmHWM to the current RSS
        mBase = statusKiB("VmRSS:");
    }
    double bytes() const { return 1024.0 * double(statusKiB("VmHWM:") - mBase); }

private:
    std::size_t mBase;
};

void report(benchmark::State& state, std::vector<double> peaks, double denseBytes)
{
    std::sort(peaks.begin(), peaks.end());
    const double peak = peaks[peaks.size() / 2];
    state.counters["peak_MiB"] = peak / (1024.0 * 1024.0);
    state.counters["peak_per_dense"] = peak / denseBytes;
}

void BM_ImportScan(benchmark::State& state)
{
    const bool mri = state.range(0) == 0;
    if (mri && !fs::exists(kMri)) return state.SkipWithError("install mricron-data");
    const fs::path raw = mri ? fs::path() : syntheticScan();
    const fs::path out = fs::temp_directory_path() / "sculpt_bench_import.vdb";
    std::vector<double> peaks;
    double dense = 1.0;
    for (auto _ : state) {
        PeakMemory memory;
        const ScanVolume scan = mri ? readScan(kMri) : readRawScan(raw, syntheticLayout());
        dense = double(scan.denseBytes());
        writeFieldImage(scanToLevelSet(scan, mri ? kMriIso : kBallIso, nativeVoxelSize(scan)), out);
        peaks.push_back(memory.bytes());
    }
    report(state, peaks, dense);
    fs::remove(out);
}

void BM_FlyingEdges(benchmark::State& state)
{
    const bool mri = state.range(0) == 0;
    if (mri && !fs::exists(kMri)) return state.SkipWithError("install mricron-data");
    const fs::path raw = mri ? fs::path() : syntheticScan();
    std::vector<double> peaks;
    double dense = 1.0;
    for (auto _ : state) {
        PeakMemory memory;
        vtkNew<vtkNIFTIImageReader> nifti;
        vtkNew<vtkImageReader2> rawReader;
        vtkAlgorithm* reader = nifti;
        if (mri) {
            nifti->SetFileName(kMri);
        } else {
            rawReader->SetFileName(raw.c_str());
            rawReader->SetFileDimensionality(3);
            rawReader->SetDataExtent(0, kSynthetic - 1, 0, kSynthetic - 1, 0, kSynthetic - 1);
            rawReader->SetDataScalarTypeToUnsignedChar();
            reader = rawReader;
        }
        vtkNew<vtkFlyingEdges3D> edges;
        edges->SetInputConnection(reader->GetOutputPort());
        edges->SetValue(0, mri ? kMriIso : kBallIso);
        edges->Update();
        benchmark::DoNotOptimize(edges->GetOutput()->GetNumberOfPoints());
        dense = mri ? 181.0 * 217.0 * 181.0 : double(kSynthetic) * kSynthetic * kSynthetic;
        peaks.push_back(memory.bytes());
    }
    report(state, peaks, dense);
}

BENCHMARK(BM_ImportScan)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_FlyingEdges)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_ImportScan)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_FlyingEdges)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace
