// SPDX-License-Identifier: Apache-2.0
#include "core/field/document_text.h"

#include <algorithm>

namespace sculpt {
namespace {

bool isControl(char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }

/// Why `text` is not short, printable text, or "".
std::string textProblem(const std::string& text, std::size_t maxBytes)
{
    if (text.size() > maxBytes) {
        return "it is " + std::to_string(text.size()) + " bytes long (at most " + std::to_string(maxBytes) + ")";
    }
    if (std::any_of(text.begin(), text.end(), isControl)) return "it holds a control character (a newline, a tab, ...)";
    return {};
}

}  // namespace

std::string pieceNameProblem(const std::string& name)
{
    return name.empty() ? "it is empty" : textProblem(name, kMaxPieceNameBytes);
}

std::string unitsProblem(const std::string& units) { return textProblem(units, kMaxUnitsBytes); }

std::string printableText(std::string text, std::size_t maxBytes)
{
    std::replace_if(text.begin(), text.end(), isControl, ' ');
    if (text.size() <= maxBytes) return text;
    std::size_t end = maxBytes;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;  // not inside a character
    return text.substr(0, end);
}

}  // namespace sculpt
