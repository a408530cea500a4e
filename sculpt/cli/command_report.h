// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file command_report.h
/// @brief What a command tells its caller on stdout: prose lines for a person, one JSON object
///        with stable keys for a script (--json; data/reports.schema.json), or nothing (--quiet).
///        Errors and warnings go to stderr in every mode.

#include "sculpt/cli/run_options.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace sculpt::cli {

class CommandReport {
public:
    /// A report of `command` (its "command" key) printed as `options` ask.
    CommandReport(const std::string& command, const RunOptions& options);

    /// Adds a line of prose (shown without --json and --quiet).
    void say(const std::string& line);
    /// Adds a line of prose formatted as printf does.
    template <typename... Args>
    void sayFormatted(const char* format, Args... args)
    {
        std::string line(std::size_t(std::snprintf(nullptr, 0, format, args...)), '\0');
        std::snprintf(line.data(), line.size() + 1, format, args...);
        say(line);
    }
    /// The JSON object's fields.
    nlohmann::json& operator[](const std::string& key) { return mJson[key]; }
    /// Records a file written: kind is "document", "mesh", "image", "labels" or "tracked".
    void wrote(const std::string& path, const std::string& kind);
    /// The last file recorded, for details of its own.
    nlohmann::json& lastOutput() { return mJson["outputs"].back(); }

    /// Prints the report.
    void print() const;

private:
    RunOptions mOptions;
    std::vector<std::string> mLines;
    nlohmann::json mJson;
};

}  // namespace sculpt::cli
