// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/frame_files.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"

#include <algorithm>
#include <cstdio>

namespace sculpt {

namespace fs = std::filesystem;

fs::path framePath(const fs::path& dir, int index, const std::string& extension)
{
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.%s", index, extension.c_str());
    return dir / name;
}

bool numberedNameLess(const std::string& a, const std::string& b)
{
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (digit(a[i]) && digit(b[j])) {
            std::size_t ei = i, ej = j;
            while (ei < a.size() && digit(a[ei])) ++ei;
            while (ej < b.size() && digit(b[ej])) ++ej;
            std::size_t si = i, sj = j;  // leading zeros do not count
            while (si + 1 < ei && a[si] == '0') ++si;
            while (sj + 1 < ej && b[sj] == '0') ++sj;
            if (ei - si != ej - sj) return ei - si < ej - sj;
            if (const int c = a.compare(si, ei - si, b, sj, ej - sj); c != 0) return c < 0;
            if (ei - i != ej - j) return ei - i < ej - j;  // the same number: fewer zeros first
            i = ei;
            j = ej;
        } else {
            if (a[i] != b[j]) return a[i] < b[j];
            ++i;
            ++j;
        }
    }
    return a.size() - i < b.size() - j;
}

std::vector<fs::path> documentsIn(const fs::path& dir)
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.is_regular_file() && lowerExtension(entry.path()) == ".vdb") files.push_back(entry.path());
    }
    if (files.empty()) throw InputError(dir.string() + ": no .vdb documents in this directory");
    std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
        return numberedNameLess(a.filename().string(), b.filename().string());
    });
    return files;
}

}  // namespace sculpt
