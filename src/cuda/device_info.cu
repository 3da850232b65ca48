// SeaSpring — MIT licence.
/// \file device_info.cu
/// \brief CUDA device query for the CUDA build.
#include <cuda_runtime.h>

#include "core/device_info.h"

namespace seaspring {

bool cudaBackendBuilt() { return true; }

std::vector<DeviceInfo> listCudaDevices(std::string* why) {
    std::vector<DeviceInfo> out;
    int n = 0;
    const cudaError_t err = cudaGetDeviceCount(&n);
    if (err != cudaSuccess) {
        if (why) *why = cudaGetErrorString(err);
        return out;
    }
    for (int i = 0; i < n; ++i) {
        cudaDeviceProp p{};
        if (cudaGetDeviceProperties(&p, i) != cudaSuccess) continue;
        out.push_back({i, p.name, p.major, p.minor, double(p.totalGlobalMem) / (1024.0 * 1024 * 1024)});
    }
    if (out.empty() && why) *why = "no CUDA device found";
    return out;
}

}  // namespace seaspring
