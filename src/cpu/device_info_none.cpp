// SeaSpring — MIT licence.
/// \file device_info_none.cpp
/// \brief Device query of a build without the CUDA backend.
#include "core/device_info.h"

namespace seaspring {

bool cudaBackendBuilt() { return false; }

std::vector<DeviceInfo> listCudaDevices(std::string* why) {
    if (why) *why = "this build has no CUDA backend (configure with -DSEASPRING_CUDA=ON)";
    return {};
}

}  // namespace seaspring
