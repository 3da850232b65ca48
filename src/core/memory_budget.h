// SeaSpring — MIT licence.
/// \file memory_budget.h
/// \brief A memory estimate before every large allocation: a case too large for the machine
///        stops with a message naming what it needed and what is available, instead of dying
///        with std::bad_alloc (or the kernel's OOM killer) half-way.
#pragma once

#include <cstdint>
#include <string>

namespace seaspring {

/// Memory the process may still take [bytes]: MemAvailable of /proc/meminfo (the physical
/// memory when it cannot be read), or SEASPRING_MEMORY_LIMIT (bytes) when that is set (tests,
/// shared machines).
std::uint64_t availableMemory();

/// The most host memory this process has held so far (its peak resident set, getrusage) [bytes].
std::uint64_t peakHostMemory();

/// "out of GPU memory: SeaSpring asked for R MiB more while its arrays held H MiB; the device had
/// F MiB free of T MiB (...); generate the case with a larger dp, ..." (bytes in; MiB with one
/// decimal out). core/device_memory.h throws it when an allocation does not fit.
std::string outOfDeviceMemoryMessage(std::uint64_t request, std::uint64_t held, std::uint64_t free_bytes,
                                     std::uint64_t total_bytes);

/// "<what> needs about N GB of memory but only M GB are available; <hint>" when `bytes` exceeds
/// availableMemory(), else "".
std::string memoryProblem(const std::string& what, double bytes, const std::string& hint);

/// Throws seaspring::Error "FILE:LINE: <what> needs about N GB of memory but only M GB are
/// available (...)" when `bytes` exceeds availableMemory(). `hint` ends the message (what to
/// change, e.g. "use a larger dp").
void checkMemory(const std::string& file, int line, const std::string& what, double bytes, const std::string& hint);

}  // namespace seaspring
