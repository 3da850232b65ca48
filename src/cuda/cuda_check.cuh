// SeaSpring — MIT licence.
/// \file cuda_check.cuh
/// \brief CUDA error checks that throw seaspring::Error naming the call and the location.
#pragma once

#include <cuda_runtime.h>

#include <string>

#include "core/error.h"

#define SEASPRING_CUDA_CHECK(call)                                                              \
    do {                                                                                        \
        const cudaError_t seaspring_err_ = (call);                                              \
        if (seaspring_err_ != cudaSuccess)                                                      \
            throw ::seaspring::Error(std::string("CUDA error in ") + #call + " at " + __FILE__ + \
                                     ":" + std::to_string(__LINE__) + ": " +                   \
                                     cudaGetErrorString(seaspring_err_));                       \
    } while (0)

/// After a kernel launch: launch errors are reported at once.
#define SEASPRING_CUDA_LAUNCH_CHECK() SEASPRING_CUDA_CHECK(cudaGetLastError())
