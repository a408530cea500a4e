// SPDX-License-Identifier: Apache-2.0
#include "ui/status/process_memory.h"

#include <fstream>
#include <string>

namespace sculpt::ui {

namespace {

/// The field of /proc/self/status named `name` (a size in kB), in bytes.
std::size_t statusBytes(const std::string& name)
{
    std::ifstream status("/proc/self/status");
    std::string field;
    std::size_t kiB = 0;
    while (status >> field) {
        if (field == name) return status >> kiB ? kiB * 1024 : 0;
        status.ignore(1 << 12, '\n');
    }
    return 0;
}

}  // namespace

std::size_t residentBytes() { return statusBytes("VmRSS:"); }

std::size_t peakResidentBytes() { return statusBytes("VmHWM:"); }

}  // namespace sculpt::ui
