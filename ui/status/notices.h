// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file notices.h
/// @brief What the window tells the user: the status line's notice (saved, cancelled, why an
///        edit waits) and an error shown until dismissed (written to stderr too, for scripts).

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace sculpt::ui {

class Notices {
public:
    void say(std::string notice) { mNotice = std::move(notice); }
    /// Clears the notice if it is `notice` (a mode's hint, once the mode is gone).
    void unsay(const std::string& notice);
    const std::string& notice() const { return mNotice; }

    void fail(const std::string& message);
    const std::string& error() const { return mError; }
    void dismiss() { mError.clear(); }

    /// "notice" and "error" in the window's report.
    void report(nlohmann::json& out) const;

private:
    std::string mNotice, mError;
};

}  // namespace sculpt::ui
