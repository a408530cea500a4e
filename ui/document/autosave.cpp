// SPDX-License-Identifier: Apache-2.0
#include "ui/document/autosave.h"

#include "core/base/errors.h"
#include "core/base/private_directory.h"
#include "core/io/vdb_file.h"
#include "sculpt/session/document.h"

#include <cstdlib>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

/// FNV-1a: stable across runs and builds, unlike std::hash.
std::uint64_t fnv1a(const std::string& text)
{
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    return h;
}

}  // namespace

Autosave::Autosave(fs::path stateDir, double intervalSeconds) : mDir(std::move(stateDir)), mInterval(intervalSeconds) {}

fs::path Autosave::stateDirectory()
{
    if (const char* xdg = std::getenv("XDG_STATE_HOME"); xdg && *xdg) return fs::path(xdg) / "sculpt";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".local" / "state" / "sculpt";
    return fs::path(".sculpt-state");
}

fs::path Autosave::recoveryFile(const fs::path& documentPath) const
{
    std::error_code ec;
    const fs::path absolute = documentPath.empty() ? fs::path() : fs::absolute(documentPath, ec);
    const std::string stem = documentPath.empty() ? "untitled" : documentPath.stem().string();
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(absolute.string())));
    return mDir / "recovery" / (stem + "-" + hash + ".vdb");
}

bool Autosave::tick(const Document& document, double nowSeconds, bool strokeActive, std::string& error)
{
    if (strokeActive || nowSeconds - mLastWrite < mInterval || !needsWrite(document)) return false;
    mLastWrite = nowSeconds;  // a failing disk is retried at the next interval, not every frame
    return save(document, error);
}

bool Autosave::save(const Document& document, std::string& error)
{
    if (!needsWrite(document)) return false;
    try {
        makePrivateDirectory(mDir / "recovery");
        document.writeCopy(recoveryFile(document.path()));
    } catch (const InputError& e) {
        error = std::string("autosave failed: ") + e.what();
        return false;
    }
    mWrittenRevision = document.revision();
    mWrittenOnce = true;
    return true;
}

bool Autosave::needsWrite(const Document& document) const
{
    return document.modified() && !(mWrittenOnce && document.revision() == mWrittenRevision);
}

std::optional<fs::path> Autosave::pending(const fs::path& documentPath) const
{
    const fs::path recovery = recoveryFile(documentPath);
    std::error_code ec;
    if (!fs::exists(recovery, ec)) return std::nullopt;
    if (!documentPath.empty() && fs::exists(documentPath, ec) &&
        fs::last_write_time(recovery, ec) <= fs::last_write_time(documentPath, ec)) {
        return std::nullopt;
    }
    return recovery;
}

void Autosave::discard(const fs::path& documentPath)
{
    std::error_code ec;
    fs::remove(recoveryFile(documentPath), ec);
}

}  // namespace sculpt::ui
