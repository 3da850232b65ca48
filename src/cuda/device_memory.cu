// SeaSpring — MIT licence.
/// \file device_memory.cu
/// \brief The device allocations' ledger (core/device_memory.h).
#include "core/device_memory.h"

#include <cuda_runtime.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "core/memory_budget.h"

namespace seaspring {
namespace {
std::atomic<std::uint64_t> held{0}, peak{0};

void notePeak(std::uint64_t now) {
    std::uint64_t p = peak.load();
    while (now > p && !peak.compare_exchange_weak(p, now)) {
    }
}
}  // namespace

void deviceAllocate(void** p, std::size_t bytes) {
    if (const char* env = std::getenv("SEASPRING_DEVICE_MEMORY_LIMIT")) {
        char* end = nullptr;
        const unsigned long long limit = std::strtoull(env, &end, 10);
        const std::uint64_t h = held.load();
        if (end != env && *end == '\0' && h + bytes > limit)
            throw OutOfDeviceMemory(outOfDeviceMemoryMessage(bytes, h, limit > h ? limit - h : 0, limit) +
                                    " (SEASPRING_DEVICE_MEMORY_LIMIT=" + env + ")");
    }
    const cudaError_t err = cudaMalloc(p, bytes);
    if (err == cudaErrorMemoryAllocation) {
        (void)cudaGetLastError();  // not sticky: cleared, the context stays usable
        std::size_t free_bytes = 0, total_bytes = 0;
        if (cudaMemGetInfo(&free_bytes, &total_bytes) != cudaSuccess) free_bytes = total_bytes = 0;
        throw OutOfDeviceMemory(outOfDeviceMemoryMessage(bytes, held.load(), free_bytes, total_bytes));
    }
    if (err != cudaSuccess)
        throw Error(std::string("CUDA error in cudaMalloc of ") + std::to_string(bytes) +
                    " bytes: " + cudaGetErrorString(err));
    notePeak(held += bytes);
}

void deviceFree(void* p, std::size_t bytes) {
    if (p == nullptr) return;
    cudaFree(p);
    std::uint64_t h = held.load();
    while (!held.compare_exchange_weak(h, h - std::min<std::uint64_t>(bytes, h))) {
    }
}

std::uint64_t deviceBytesHeld() { return held.load(); }
std::uint64_t deviceBytesPeak() { return peak.load(); }
void resetDevicePeak() { peak.store(held.load()); }

}  // namespace seaspring
