// SPDX-License-Identifier: Apache-2.0
#include "core/scan/header_text.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"

#include <cmath>
#include <cstdlib>

namespace sculpt {

std::string trimmed(const std::string& text)
{
    const auto first = text.find_first_not_of(" \t\r");
    const auto last = text.find_last_not_of(" \t\r");
    return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

std::vector<std::string> headerLines(std::istream& in, const std::string& where, std::size_t& bytes,
                                     const std::function<bool(const std::string&)>& isEnd)
{
    std::vector<std::string> lines;
    bytes = 0;
    for (std::string line;;) {
        if (!std::getline(in, line)) return lines;  // a detached header may end with the file
        bytes += line.size() + 1;
        if (bytes > kMaxHeaderBytes || line.find('\0') != std::string::npos)
            throw InputError(where + "not a text header (binary bytes, or no end within 64 KiB)");
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (isEnd(line)) return lines;
        lines.push_back(line);
    }
}

std::vector<double> finiteNumbers(const std::string& text, const std::string& where, const std::string& field)
{
    std::vector<double> numbers;
    const char* p = text.c_str();
    const auto separator = [](char c) {
        return c == ' ' || c == '\t' || c == ',' || c == '(' || c == ')' || c == '\\';
    };
    while (*p) {
        if (separator(*p)) {
            ++p;
            continue;
        }
        char* end = nullptr;
        const double value = std::strtod(p, &end);
        if (end == p || !std::isfinite(value) || (*end && !separator(*end)))
            throw InputError(where + field + " '" + text.substr(0, 80) +
                             "' holds something that is not a finite number");
        numbers.push_back(value);
        p = end;
    }
    return numbers;
}

HeaderFields::HeaderFields(const std::vector<std::string>& lines, const std::string& separator)
{
    for (const std::string& line : lines) {
        const auto at = line.find(separator);
        if (at != std::string::npos) mFields[trimmed(line.substr(0, at))] = trimmed(line.substr(at + separator.size()));
    }
}

std::string HeaderFields::text(const std::string& key) const
{
    const auto found = mFields.find(key);
    return found == mFields.end() ? std::string() : found->second;
}

std::vector<double> HeaderFields::numbers(const std::string& key, const std::string& where) const
{
    return has(key) ? finiteNumbers(text(key), where, key) : std::vector<double>{};
}

double sampleCount(const std::vector<double>& sizes, const std::string& where, const std::string& field)
{
    double product = 1.0;
    for (const double n : sizes) {
        if (!(n >= 1.0) || n != std::floor(n))
            throw InputError(where + field + " holds " + formatNumber(n) + ": not a size");
        product *= n;
    }
    if (sizes.empty() || product > kMaxScanSamples)
        throw InputError(where + field + " gives " + formatNumber(product) + " samples: no scan's size");
    return product;
}

void requireSpacings(const std::vector<double>& spacings, const std::string& where, const std::string& field)
{
    for (const double s : spacings) {
        if (!std::isfinite(s)) throw InputError(where + field + " gives a spacing of " + formatNumber(s));
        if (!(std::abs(s) >= kMinSampleSpacing)) {
            throw InputError(where + field + " gives a spacing of " + formatNumber(s) + ", below the smallest (" +
                             formatNumber(kMinSampleSpacing) + ")");
        }
    }
}

}  // namespace sculpt
