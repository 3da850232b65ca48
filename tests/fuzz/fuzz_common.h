// SeaSpring — MIT licence.
/// \file fuzz_common.h
/// \brief What the fuzz targets share: a scratch folder of this process, writing an input to a
///        file there, and the rule that an input may only end in seaspring::Error (or a
///        model::ValueError): any other exception, a crash, a sanitizer report, a hang or a
///        huge allocation is a finding.
#pragma once

#include <cstdint>
#include <cstdio>
#include <exception>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace seaspring::fuzz {

/// TMPDIR/seaspring_fuzz_PID (created once).
inline const std::string& scratchDir() {
    static const std::string dir = [] {
        const char* tmp = std::getenv("TMPDIR");
        const std::string d = std::string(tmp && *tmp ? tmp : "/tmp") + "/seaspring_fuzz_" + std::to_string(::getpid());
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

/// Writes the input bytes to scratchDir()/name and returns the path.
inline std::string writeInput(const std::string& name, const std::uint8_t* data, std::size_t size) {
    const std::string path = scratchDir() + "/" + name;
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path;
}

/// Bounds what an input may make the programs allocate (core/memory_budget.h reads it): a
/// case asking for more stops with its "needs about N GB" error, which is a handled outcome.
/// One OpenMP thread (gencase paints in parallel): fuzzing runs many processes side by side.
inline void limitMemory() {
    ::setenv("SEASPRING_MEMORY_LIMIT", "67108864", 1);  // 64 MiB
    ::setenv("OMP_NUM_THREADS", "1", 0);
}

/// A handled error: printed with SEASPRING_FUZZ_VERBOSE set (to see how far a seed gets).
inline void handled(const std::exception& e) {
    if (std::getenv("SEASPRING_FUZZ_VERBOSE")) std::fprintf(stderr, "handled: %s\n", e.what());
}

}  // namespace seaspring::fuzz
