// SPDX-License-Identifier: Apache-2.0
#include "core/base/warning_summary.h"

#include <cctype>
#include <map>

namespace sculpt {

namespace {

/// What makes two warnings alike: the text after a "piece '...': " prefix, digits blanked.
std::string kindOf(const std::string& warning)
{
    std::string text = warning;
    if (text.rfind("piece '", 0) == 0) {
        const std::size_t end = text.find("': ");
        if (end != std::string::npos) text = text.substr(end + 3);
    }
    std::string kind;
    for (const char c : text)
        if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.') kind += c;
    return kind;
}

}  // namespace

std::vector<std::string> summarisedWarnings(const std::vector<std::string>& warnings, std::size_t keep)
{
    std::map<std::string, std::size_t> seen, total;
    for (const std::string& warning : warnings) ++total[kindOf(warning)];
    std::vector<std::string> said;
    for (const std::string& warning : warnings) {
        const std::string kind = kindOf(warning);
        const std::size_t n = ++seen[kind];
        if (n <= keep) said.push_back(warning);
        if (n == keep && total[kind] > keep)
            said.push_back("... and " + std::to_string(total[kind] - keep) + " more like it (--verbose lists them)");
    }
    return said;
}

}  // namespace sculpt
