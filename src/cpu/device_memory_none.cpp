// SeaSpring — MIT licence.
/// \file device_memory_none.cpp
/// \brief The device allocations of a build without the CUDA backend: none (core/device_memory.h).
#include "core/device_memory.h"

#include "core/error.h"

namespace seaspring {

void deviceAllocate(void**, std::size_t) {
    throw Error("no device memory: this build has no CUDA backend (configure with -DSEASPRING_CUDA=ON)");
}
void deviceFree(void*, std::size_t) {}
std::uint64_t deviceBytesHeld() { return 0; }
std::uint64_t deviceBytesPeak() { return 0; }
void resetDevicePeak() {}

}  // namespace seaspring
