// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file text_lines.h
/// @brief The lines of a text file as words, for the mesh readers (OBJ, OFF, text PLY and STL):
///        comments dropped, empty lines skipped, every number checked, errors naming the file
///        and the line.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sculpt {

/// A whole file in memory, refused beforehand if it exceeds what the machine has.
std::string readWholeFile(const std::filesystem::path& path);

class TextLines {
public:
    /// Lines of `text` (a view into a buffer that outlives this), starting at line `firstLine`;
    /// from `comment` to the end of a line is dropped ('\0': no comments).
    TextLines(std::string_view text, const std::filesystem::path& path, char comment = '\0', int firstLine = 1);

    /// The next line's words; empty at the end of the text.
    const std::vector<std::string_view>& next();
    /// Whether the text is used up.
    bool atEnd() const { return mAt >= mText.size(); }

    /// `word` as a finite number. @throws InputError naming the file, the line and `what`.
    double number(std::string_view word, const std::string& what) const;
    /// `word` as a whole number. @throws InputError as number().
    std::int64_t integer(std::string_view word, const std::string& what) const;
    /// An InputError naming the file and the current line.
    [[noreturn]] void fail(const std::string& message) const;

private:
    std::string_view mText;
    std::filesystem::path mPath;
    char mComment;
    std::size_t mAt = 0;
    int mLine;
    std::vector<std::string_view> mWords;
};

}  // namespace sculpt
