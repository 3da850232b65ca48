// SeaSpring — MIT licence.
/// \file memory_budget.cpp
/// \brief Available memory and the check before large allocations (see memory_budget.h).
#include "core/memory_budget.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/error.h"

namespace seaspring {

std::uint64_t availableMemory() {
    if (const char* env = std::getenv("SEASPRING_MEMORY_LIMIT")) {
        char* end = nullptr;
        const unsigned long long v = std::strtoull(env, &end, 10);
        if (end != env && *end == '\0') return v;
    }
    std::ifstream in("/proc/meminfo");
    for (std::string line; std::getline(in, line);) {
        std::istringstream s(line);
        std::string key;
        unsigned long long kb = 0;
        if (s >> key >> kb && key == "MemAvailable:") return std::uint64_t(kb) * 1024u;
    }
    const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? std::uint64_t(pages) * std::uint64_t(size) : UINT64_MAX;
}

std::string memoryProblem(const std::string& what, double bytes, const std::string& hint) {
    const double avail = double(availableMemory());
    if (!(bytes > avail)) return "";
    char b[160];
    std::snprintf(b, sizeof b, " needs about %.3g GB of memory but only %.3g GB are available", bytes / 1e9,
                  avail / 1e9);
    return what + b + (hint.empty() ? "" : "; " + hint);
}

void checkMemory(const std::string& file, int line, const std::string& what, double bytes, const std::string& hint) {
    const std::string m = memoryProblem(what, bytes, hint);
    if (!m.empty()) throwInputError(file, line, m);
}

}  // namespace seaspring
