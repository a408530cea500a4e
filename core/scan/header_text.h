// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file header_text.h
/// @brief What the text headers of NRRD and MetaImage files share: lines read with a bound,
///        `key: value` fields, and numbers parsed strictly. Internal to scan/ (header_checks.h).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace sculpt {

/// A header may be this long: real ones are a few hundred bytes.
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
/// Samples a scan may declare (a header's product of sizes).
constexpr double kMaxScanSamples = double(1LL << 40);
/// Smallest sample spacing a header may declare, in its units (10 micrometres in metres): a
/// spacing of 10^-6 is damage, not a scan, and would be imported at a voxel size no model may
/// have (kMinVoxelSize, field_image.h).
constexpr double kMinSampleSpacing = 1e-5;

std::string trimmed(const std::string& text);

/// The header lines up to (not including) the line `isEnd` is true for, or to the end of the
/// stream; their bytes (newlines included) in `bytes`.
/// @throws InputError (`where` + what) for a NUL byte or more than kMaxHeaderBytes.
std::vector<std::string> headerLines(std::istream& in, const std::string& where, std::size_t& bytes,
                                     const std::function<bool(const std::string&)>& isEnd);

/// The numbers in `text`, separated by spaces, commas, parentheses or backslashes.
/// @throws InputError naming `where` and `field` if one is not a finite number.
std::vector<double> finiteNumbers(const std::string& text, const std::string& where, const std::string& field);

/// A header's fields by name, as `key<separator>value` lines give them.
class HeaderFields {
public:
    HeaderFields(const std::vector<std::string>& lines, const std::string& separator);

    bool has(const std::string& key) const { return mFields.count(key) > 0; }
    /// The value, empty if absent.
    std::string text(const std::string& key) const;
    /// The field's finite numbers (none if absent). @throws InputError otherwise.
    std::vector<double> numbers(const std::string& key, const std::string& where) const;

private:
    std::map<std::string, std::string> mFields;
};

/// Positive whole sizes, their product at most kMaxScanSamples. @return the product.
/// @throws InputError naming `field` otherwise.
double sampleCount(const std::vector<double>& sizes, const std::string& where, const std::string& field);

/// Spacings finite and at least kMinSampleSpacing in size (a sign is an orientation).
/// @throws InputError naming `field` otherwise.
void requireSpacings(const std::vector<double>& spacings, const std::string& where, const std::string& field);

}  // namespace sculpt
