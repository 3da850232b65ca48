// SeaSpring — MIT licence.
/// \file memory_budget.cpp
/// \brief Available memory and the check before large allocations (see memory_budget.h).
#include "core/memory_budget.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
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

std::uint64_t peakHostMemory() {
    struct rusage u {};
    if (::getrusage(RUSAGE_SELF, &u) != 0) return 0;
    return std::uint64_t(u.ru_maxrss) * 1024u;  // Linux: kilobytes
}

std::string outOfDeviceMemoryMessage(std::uint64_t request, std::uint64_t held, std::uint64_t free_bytes,
                                     std::uint64_t total_bytes) {
    const double mib = 1024.0 * 1024.0;
    char b[512];
    std::snprintf(b, sizeof b,
                  "out of GPU memory: SeaSpring asked for %.1f MiB more while its arrays held %.1f MiB; the device "
                  "had %.1f MiB free of %.1f MiB (the CUDA context and other processes hold the rest); generate "
                  "the case with a larger dp, free the GPU, or run on the CPU (-cpu)",
                  double(request) / mib, double(held) / mib, double(free_bytes) / mib, double(total_bytes) / mib);
    return b;
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
