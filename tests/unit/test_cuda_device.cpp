// SeaSpring — MIT licence.
/// \file test_cuda_device.cpp
/// \brief The CUDA device query. Skips, saying why, on machines without a GPU or without the
///        CUDA backend; on a GPU machine it checks the device is a Hopper (sm_90) build target.
#include <gtest/gtest.h>

#include "core/device_info.h"

TEST(CudaDevice, QueryReportsDevicesOrWhyNot) {
    std::string why;
    const auto devices = seaspring::listCudaDevices(&why);
    if (devices.empty()) {
        EXPECT_FALSE(why.empty());
        GTEST_SKIP() << "no CUDA device: " << why;
    }
    EXPECT_TRUE(seaspring::cudaBackendBuilt());
    for (const auto& d : devices) {
        EXPECT_FALSE(d.name.empty());
        EXPECT_GT(d.memory_gib, 1.0);
        // The build targets compute capability 9.0 (H100/H200).
        EXPECT_GE(d.major, 9) << d.name << " is sm_" << d.major << d.minor;
    }
}
