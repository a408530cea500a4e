#include "core/base/memory_budget.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"

#include <unistd.h>

#include <fstream>

namespace sculpt {

std::uint64_t availableMemoryBytes()
{
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit) {
        if (key == "MemAvailable:") return kib * 1024;
    }
    return std::uint64_t(sysconf(_SC_PHYS_PAGES)) * std::uint64_t(sysconf(_SC_PAGE_SIZE));
}

void requireMemory(double bytes, const std::string& what)
{
    const double available = double(availableMemoryBytes());
    if (!(bytes <= available)) {
        throw InputError(what + " needs about " + formatBytes(bytes) + " of memory but only " + formatBytes(available) +
                         " is available");
    }
}

}  // namespace sculpt
