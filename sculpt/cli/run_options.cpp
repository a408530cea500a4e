// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/run_options.h"

#include "sculpt/cli/number_checks.h"
#include "sculpt/cli/progress_bar.h"

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <memory>

namespace sculpt::cli {

void addRunOptions(CLI::App& cmd, RunOptions& options, const std::string& jsonHelp)
{
    cmd.add_option("--threads", options.threads,
                   "worker threads (default: every core); results are the same bit for bit whatever the count")
        ->check(positiveNumber());
    CLI::Option* quiet =
        cmd.add_flag("-q,--quiet", options.quiet, "print nothing but errors and warnings (no report, no progress bar)");
    cmd.add_flag("--json", options.json,
                 "print the report as one JSON object on stdout: its command, outputs (each file written\n"
                 "with its path and kind) and the command's own keys (data/reports.schema.json)" +
                     (jsonHelp.empty() ? "" : ";\n" + jsonHelp))
        ->excludes(quiet);
    cmd.parse_complete_callback([&options] {
        static std::unique_ptr<tbb::global_control> threadLimit;  // for the one command a run makes
        if (options.threads > 0)
            threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                                std::size_t(options.threads));
        if (options.quiet) ProgressBar::hideAll();
    });
}

}  // namespace sculpt::cli
