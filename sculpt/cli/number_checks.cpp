// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/number_checks.h"

#include <cmath>
#include <functional>
#include <string>

namespace sculpt::cli {

namespace {

CLI::Validator numberAbove(const char* description, const std::function<bool(double)>& accepts)
{
    return CLI::Validator(
        [description, accepts](std::string& text) -> std::string {
            double value = 0.0;
            if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !accepts(value)) {
                return std::string("must be ") + description + " (got " + text + ")";
            }
            return {};
        },
        description);
}

}  // namespace

CLI::Validator positiveNumber()
{
    return numberAbove("a positive number", [](double v) { return v > 0.0; });
}

CLI::Validator nonNegativeNumber()
{
    return numberAbove("a number >= 0", [](double v) { return v >= 0.0; });
}

}  // namespace sculpt::cli
