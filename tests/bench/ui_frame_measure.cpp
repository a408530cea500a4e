// SPDX-License-Identifier: Apache-2.0
// A scripted measurement of sculpt-ui under Mesa's software OpenGL (not a Google Benchmark: the
// figures come from replayed sessions, as a person would see them). For each model it replays 3 s
// still (static frame), a 10-second stroke at 60 events a second, a 3-second orbit drag and 30
// key-orbit steps, and prints medians and 95th percentiles, triangles drawn, actors, stamps per
// second, opening times (first frame, preview, full detail) and peak memory. The models are issue
// 31's: the clay ball, and ch2better (mricron-data) imported at 0.5 mm and at 0.25 mm (8 M
// triangles), made at run time.
// Run by hand (about 12 minutes; the 0.25 mm model alone about 6):
//   build/tests/bench/ui_frame_measure [--reference] [--chunk C]... [--document DOC.vdb]
// --reference adds, for each model, the display of one actor per block it had before chunks;
// --chunk C adds the display with chunks of C^3 blocks (the default chooses C from the model).
// Figures go in the issue notes.

#include "tests/support/run_sculpt.h"
#include "tests/support/temp_dir.h"
#include "tests/ui/ui_driver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <regex>
#include <string>

namespace {

using namespace sculpt::test;
using nlohmann::json;

const char* const kScan = "/usr/share/mricron/templates/ch2better.nii.gz";

double percentile(std::vector<double> v, double q)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5))];
}

std::vector<double> numbers(const json& list) { return list.get<std::vector<double>>(); }

/// The seconds at which sculpt-ui says `stage` ("first frame", "preview", "full detail") came,
/// or -1 if it did not say (a small model has no preview).
double stageSeconds(const std::string& out, const std::string& stage)
{
    std::smatch m;
    return std::regex_search(out, m, std::regex(stage + " in ([0-9.e+-]+) s")) ? std::stod(m[1]) : -1.0;
}

/// When the model came on screen: the window, its preview, full detail.
struct Opening {
    double firstFrame = -1.0, preview = -1.0, fullDetail = -1.0;
};

std::string secondsOrNone(double s) { return s < 0.0 ? "none" : std::to_string(s).substr(0, 4) + " s"; }

void line(const char* what, const std::vector<double>& ms)
{
    std::printf("  %-28s median %6.1f ms  p95 %6.1f ms  max %6.1f ms  (%zu frames, %.1f fps)\n", what,
                percentile(ms, 0.5), percentile(ms, 0.95), percentile(ms, 1.0), ms.size(),
                1000.0 / std::max(1e-9, percentile(ms, 0.5)));
}

void summarise(const std::string& model, const Reports& r, const Opening& opening)
{
    const json& still = r["still"];
    std::printf("%s: %zu triangles, %zu blocks, %zu chunks (C = %d), %zu actors\n", model.c_str(),
                still["triangles"].get<std::size_t>(), still["blocks"].get<std::size_t>(),
                still["chunks"].get<std::size_t>(), still["chunk_blocks"].get<int>(),
                still["actors"].get<std::size_t>());
    std::printf("  %-28s first frame %s, preview %s, full detail %s\n", "opening",
                secondsOrNone(opening.firstFrame).c_str(), secondsOrNone(opening.preview).c_str(),
                secondsOrNone(opening.fullDetail).c_str());
    line("static", numbers(still["frame_times_ms"]));
    line("sculpting (10 s stroke)", numbers(r["stroked"]["frame_times_ms"]));
    const std::vector<double> latency = numbers(r["stroked"]["latencies_ms"]);
    std::printf("  %-28s median %6.1f ms  p95 %6.1f ms\n", "event -> stamp on screen", percentile(latency, 0.5),
                percentile(latency, 0.95));
    const double stamps = r["stroked"]["stamps"];
    std::printf("  %-28s %.0f stamps in 10 s: %.1f per second; %.0f KiB uploaded per stamp vs %.0f KiB whole mesh\n",
                "stamps", stamps, stamps / 10.0,
                r["stroked"]["bytes_uploaded"].get<double>() / std::max(1.0, stamps) / 1024.0,
                r["stroked"]["mesh_bytes"].get<double>() / 1024.0);
    line("orbit, mouse drag", numbers(r["orbiting"]["frame_times_ms"]));
    line("orbit, keys", numbers(r["keyed"]["frame_times_ms"]));
    const auto drawn = [&](const char* report) {
        return percentile(numbers(r[report]["triangles_drawn_per_frame"]), 0.5);
    };
    std::printf("  %-28s still %.0f, sculpting %.0f, orbiting %.0f, keys %.0f (medians of their frames)\n",
                "triangles drawn", drawn("still"), drawn("stroked"), drawn("orbiting"), drawn("keyed"));
    const double peak = std::max(r["stroked"]["peak_rss"].get<double>(), r["keyed"]["peak_rss"].get<double>());
    const json& memory = still["memory"];
    const auto gb = [&](const char* part) { return memory[part].get<double>() / 1e9; };
    std::printf("  %-28s %.2f GB; resident when still %.2f GB: grid %.2f, mesher %.2f, display %.2f, undo %.2f\n",
                "peak RSS", peak / 1e9, gb("resident"), gb("grid"), gb("mesher"), gb("display"), gb("undo"));
}

/// The replay's stdout, or nothing if sculpt-ui failed.
std::optional<std::string> replay(const UiEvents& events, const std::string& document, const std::string& extra,
                                  const TempDir& dir)
{
    events.write(dir / "events.json");
    const CommandResult run = runUi(document + " --play '" + (dir / "events.json").string() + "' --state-dir '" +
                                        (dir / "state").string() + "' " + extra,
                                    dir.path().string());
    if (run.exitCode != 0) {
        std::cerr << "sculpt-ui failed: " << run.err << "\n";
        return std::nullopt;
    }
    return run.out;
}

/// Two runs, so a stroke that falls behind its schedule cannot crowd the orbits' events.
void measure(const std::string& model, const std::string& document, const std::string& extra, const TempDir& dir)
{
    const auto r = dir / (model + ".jsonl");
    std::filesystem::remove(r);
    UiEvents sculpting;
    // "opened" closes the frames of the opening (the preview, the fill-in): "still" is 3 s of rest.
    sculpting.move(760, 400).report(r, "opened").wait(3.0).report(r, "still").press();
    for (int i = 1; i <= 600; ++i) {  // 10 s at 60 Hz, circles of 120 px
        const double a = 2.0 * M_PI * i / 150.0;
        sculpting.wait(1.0 / 60.0 - 0.02).move(640 + 120 * std::cos(a), 400 + 120 * std::sin(a));
    }
    sculpting.release().report(r, "stroked");
    UiEvents orbit;
    orbit.move(200, 650).wait(1.0).report(r, "orbit-start").press("right");
    for (int i = 1; i <= 180; ++i) orbit.wait(1.0 / 60.0 - 0.02).move(200 + 3 * i, 650);
    orbit.report(r, "orbiting").release("right").wait(1.0).report(r, "keys-start");
    for (int i = 0; i < 30; ++i) orbit.wait(0.1).key("Right");
    orbit.report(r, "keyed");
    const std::optional<std::string> first = replay(sculpting, document, extra, dir);
    if (!first || !replay(orbit, document, extra, dir)) return;
    const Opening opening{stageSeconds(*first, "first frame"), stageSeconds(*first, "preview"),
                          stageSeconds(*first, "full detail")};
    summarise(model, Reports(r), opening);
}

/// The display as it chooses its chunks, then with each chunk size of `chunkSizes` (1: a chunk per block).
void measureChunkSizes(const std::string& model, const std::string& document, const std::vector<int>& chunkSizes,
                       const TempDir& dir)
{
    measure(model, document, "", dir);
    for (int c : chunkSizes) {
        const std::string label = c == 1 ? " (a chunk per block)" : " (C = " + std::to_string(c) + ")";
        measure(model + label, document, "--display-chunk " + std::to_string(c), dir);
    }
}

}  // namespace

int main(int argc, char** argv)
{
    TempDir dir;
    std::vector<int> chunkSizes;
    std::string document;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--reference") chunkSizes.push_back(1);
        else if (arg == "--chunk" && i + 1 < argc && std::atoi(argv[i + 1]) > 0)
            chunkSizes.push_back(std::atoi(argv[++i]));
        else if (arg == "--document" && i + 1 < argc) document = std::filesystem::absolute(argv[++i]).string();
        else {
            std::cerr << "usage: ui_frame_measure [--reference] [--chunk C]... [--document DOC.vdb]\n";
            return 2;
        }
    }
    if (!document.empty()) {  // a model of your own, e.g. an imported scan
        measureChunkSizes(std::filesystem::path(document).filename().string(), "'" + document + "'", chunkSizes, dir);
        return 0;
    }
    measureChunkSizes("clay ball", "", chunkSizes, dir);
    for (const char* voxel : {"0.5", "0.25"}) {
        const std::string name = std::string("ch2better-") + voxel + ".vdb";
        const CommandResult made =
            runSculpt(std::string("import ") + kScan + " --largest-component --voxel-size " + voxel + " -o " + name,
                      dir.path().string());
        if (made.exitCode != 0) {
            std::cerr << "could not import " << kScan << ": " << made.err << "\n";
            return 1;
        }
        measureChunkSizes("ch2better at " + std::string(voxel) + " mm", "'" + (dir / name).string() + "'", chunkSizes,
                          dir);
    }
    return 0;
}
