// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/command_report.h"

#include <iostream>

namespace sculpt::cli {

CommandReport::CommandReport(const std::string& command, const RunOptions& options) : mOptions(options)
{
    mJson["command"] = command;
    mJson["outputs"] = nlohmann::json::array();
}

void CommandReport::say(const std::string& line) { mLines.push_back(line); }

void CommandReport::wrote(const std::string& path, const std::string& kind)
{
    mJson["outputs"].push_back({{"path", path}, {"kind", kind}});
}

void CommandReport::print() const
{
    if (mOptions.quiet) return;
    if (mOptions.json) {
        std::cout << mJson.dump() << "\n";
        return;
    }
    for (const std::string& line : mLines) std::cout << line << "\n";
}

}  // namespace sculpt::cli
