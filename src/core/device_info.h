// SeaSpring — MIT licence.
/// \file device_info.h
/// \brief Which CUDA devices this process can use (none in a build without CUDA).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace seaspring {

struct DeviceInfo {
    int index = 0;
    std::string name;
    int major = 0, minor = 0;   ///< compute capability
    double memory_gib = 0;
};

/// A backend's device memory: the bytes its arrays hold now and held at most (the process's
/// allocations through core/device_memory.h), and the device's whole memory. All zero on the
/// CPU backend, whose arrays are in the host's memory (peakHostMemory, memory_budget.h).
struct DeviceMemoryUse {
    std::uint64_t held = 0, peak = 0, total = 0;
};

/// True when the binary was built with the CUDA backend.
bool cudaBackendBuilt();
/// Devices visible to the CUDA runtime; empty without CUDA, driver or device. `why` (if not
/// null) receives the reason when the list is empty.
std::vector<DeviceInfo> listCudaDevices(std::string* why = nullptr);

}  // namespace seaspring
