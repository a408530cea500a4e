// SPDX-License-Identifier: Apache-2.0
#include "ui/status/notices.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace sculpt::ui {

void Notices::unsay(const std::string& notice)
{
    if (mNotice == notice) mNotice.clear();
}

void Notices::fail(const std::string& message)
{
    mError = message;
    std::cerr << "sculpt-ui: " << message << "\n";
}

void Notices::report(nlohmann::json& out) const
{
    out["notice"] = mNotice;
    out["error"] = mError;
}

}  // namespace sculpt::ui
