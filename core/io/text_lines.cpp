// SPDX-License-Identifier: Apache-2.0
#include "core/io/text_lines.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>

namespace sculpt {

namespace fs = std::filesystem;

std::string readWholeFile(const fs::path& path)
{
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) throw InputError(path.string() + ": cannot read the file");
    requireMemory(double(size), path.string());
    std::ifstream in(path, std::ios::binary);
    std::string bytes(size, '\0');
    if (!in.read(bytes.data(), std::streamsize(size))) throw InputError(path.string() + ": cannot read the file");
    return bytes;
}

TextLines::TextLines(std::string_view text, const fs::path& path, char comment, int firstLine)
    : mText(text), mPath(path), mComment(comment), mLine(firstLine - 1)
{}

const std::vector<std::string_view>& TextLines::next()
{
    mWords.clear();
    while (mWords.empty() && mAt < mText.size()) {
        std::size_t end = mText.find('\n', mAt);
        if (end == std::string_view::npos) end = mText.size();
        std::string_view line = mText.substr(mAt, end - mAt);
        mAt = end + 1;
        ++mLine;
        if (mComment != '\0') line = line.substr(0, line.find(mComment));
        for (std::size_t i = 0; i < line.size();) {
            while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
            const std::size_t start = i;
            while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
            if (i > start) mWords.push_back(line.substr(start, i - start));
        }
    }
    return mWords;
}

void TextLines::fail(const std::string& message) const
{
    throw InputError(mPath.string() + ": line " + std::to_string(mLine) + ": " + message);
}

double TextLines::number(std::string_view word, const std::string& what) const
{
    double value = 0.0;
    const char* end = word.data() + word.size();
    const auto [used, error] = std::from_chars(word.data() + (word.size() > 1 && word[0] == '+'), end, value);
    if (error != std::errc() || used != end || !std::isfinite(value)) {
        fail(what + " has \"" + std::string(word) + "\", not a number");
    }
    return value;
}

std::int64_t TextLines::integer(std::string_view word, const std::string& what) const
{
    std::int64_t value = 0;
    const char* end = word.data() + word.size();
    const auto [used, error] = std::from_chars(word.data() + (word.size() > 1 && word[0] == '+'), end, value);
    if (error != std::errc() || used != end) fail(what + " has \"" + std::string(word) + "\", not a whole number");
    return value;
}

}  // namespace sculpt
