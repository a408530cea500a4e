// A scripted measurement of sculpt-ui under Mesa's software OpenGL (not a Google Benchmark: the
// figures come from one replayed session per model, as a person would see them). For each model
// it replays: 3 s still (static frame time), a 10-second stroke at 60 events a second, a 3-second
// orbit drag, and prints medians and 95th percentiles. Run by hand:
//   build/tests/bench/ui_frame_measure [--big-radius 80 | --document DOC.vdb]
// Figures go in the issue notes.

#include "tests/support/temp_dir.h"
#include "tests/ui/ui_driver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

namespace {

using namespace sculpt::test;
using nlohmann::json;

double percentile(std::vector<double> v, double q)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5))];
}

std::vector<double> numbers(const json& list) { return list.get<std::vector<double>>(); }

void summarise(const std::string& model, const Reports& r)
{
    const auto line = [&](const char* what, const std::vector<double>& ms) {
        std::printf("  %-28s median %6.1f ms  p95 %6.1f ms  (%zu frames, %.1f fps)\n", what, percentile(ms, 0.5),
                    percentile(ms, 0.95), ms.size(), 1000.0 / std::max(1e-9, percentile(ms, 0.5)));
    };
    std::printf("%s: %zu triangles, %zu blocks, %zu chunks (C = %d), %zu actors\n", model.c_str(),
                r["still"]["triangles"].get<std::size_t>(), r["still"]["blocks"].get<std::size_t>(),
                r["still"]["chunks"].get<std::size_t>(), r["still"]["chunk_blocks"].get<int>(),
                r["still"]["actors"].get<std::size_t>());
    line("static", numbers(r["still"]["frame_times_ms"]));
    line("sculpting (10 s stroke)", numbers(r["stroked"]["frame_times_ms"]));
    const std::vector<double> latency = numbers(r["stroked"]["latencies_ms"]);
    std::printf("  %-28s median %6.1f ms  p95 %6.1f ms\n", "event -> stamp on screen", percentile(latency, 0.5),
                percentile(latency, 0.95));
    const double stamps = r["stroked"]["stamps"];
    std::printf("  %-28s %.0f stamps in 10 s: %.1f per second; %.0f KiB uploaded per stamp vs %.0f KiB whole mesh\n",
                "stamps", stamps, stamps / 10.0,
                r["stroked"]["bytes_uploaded"].get<double>() / std::max(1.0, stamps) / 1024.0,
                r["stroked"]["mesh_bytes"].get<double>() / 1024.0);
    line(r["orbiting"]["coarse"].get<bool>() ? "orbit (coarse display)" : "orbit (full detail)",
         numbers(r["orbiting"]["frame_times_ms"]));
    std::printf("  %-28s still %zu, orbiting %zu\n", "triangles drawn",
                r["still"]["triangles_drawn"].get<std::size_t>(), r["orbiting"]["triangles_drawn"].get<std::size_t>());
}

CommandResult replay(const UiEvents& events, const std::string& document, const std::string& extra, const TempDir& dir)
{
    events.write(dir / "events.json");
    const CommandResult run = runUi(document + " --play '" + (dir / "events.json").string() + "' --state-dir '" +
                                        (dir / "state").string() + "' " + extra,
                                    dir.path().string());
    if (run.exitCode != 0) std::cerr << "sculpt-ui failed: " << run.err << "\n";
    std::cout << run.out;
    return run;
}

/// Two runs, so a stroke that falls behind its schedule cannot crowd the orbit's events.
void measure(const std::string& model, const std::string& document, const std::string& extra, const TempDir& dir)
{
    const auto r = dir / (model + ".jsonl");
    UiEvents sculpting;
    sculpting.move(760, 400).wait(3.0).report(r, "still").press();
    for (int i = 1; i <= 600; ++i) {  // 10 s at 60 Hz, circles of 120 px
        const double a = 2.0 * M_PI * i / 150.0;
        sculpting.wait(1.0 / 60.0 - 0.02).move(640 + 120 * std::cos(a), 400 + 120 * std::sin(a));
    }
    sculpting.release().report(r, "stroked");
    UiEvents orbit;
    orbit.move(200, 650).wait(1.0).report(r, "orbit-start").press("right");
    for (int i = 1; i <= 180; ++i) orbit.wait(1.0 / 60.0 - 0.02).move(200 + 3 * i, 650);
    orbit.report(r, "orbiting").release("right");
    if (replay(sculpting, document, extra, dir).exitCode != 0 || replay(orbit, document, extra, dir).exitCode != 0)
        return;
    summarise(model, Reports(r));
}

}  // namespace

int main(int argc, char** argv)
{
    TempDir dir;
    if (argc > 2 && std::string(argv[1]) == "--document") {  // a model of your own, e.g. an imported scan
        const std::filesystem::path document = std::filesystem::absolute(argv[2]);
        const std::string name = document.filename().string(), quoted = "'" + document.string() + "'";
        measure(name, quoted, "", dir);
        measure(name + " (a chunk per block)", quoted, "--display-chunk 1", dir);
        return 0;
    }
    const std::string radius = argc > 2 && std::string(argv[1]) == "--big-radius" ? argv[2] : "80";
    measure("clay ball", "", "", dir);
    const CommandResult made = runSculpt("new --radius " + radius + " -o big.vdb", dir.path().string());
    if (made.exitCode != 0) return 1;
    measure("big ball (LOD)", "big.vdb", "", dir);
    measure("big ball (no LOD)", "big.vdb", "--lod-triangles 1000000000", dir);
    // The reference: one actor per block, as the display drew before it had chunks.
    measure("big ball (a chunk per block)", "big.vdb", "--display-chunk 1", dir);
    return 0;
}
