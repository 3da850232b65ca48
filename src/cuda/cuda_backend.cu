// SeaSpring — MIT licence.
/// \file cuda_backend.cu
/// \brief The CUDA backend: the engine (solver/engine.h) over the CUDA execution policy.
#include <memory>
#include <string>

#include "cuda/cuda_exec.cuh"
#include "solver/engine.h"

namespace seaspring::solver {
std::unique_ptr<Backend> makeCudaBackend(int device, std::string& why, int host_threads) {
    int count = 0;
    const cudaError_t err = cudaGetDeviceCount(&count);
    if (err != cudaSuccess || count == 0) {
        why = err != cudaSuccess ? std::string("no CUDA device: ") + cudaGetErrorString(err)
                                 : std::string("no CUDA device found");
        return nullptr;
    }
    if (device < 0 || device >= count) {
        why = "CUDA device " + std::to_string(device) + " does not exist (devices: 0.." +
              std::to_string(count - 1) + ")";
        return nullptr;
    }
    return std::make_unique<Engine<cuda::CudaExec>>(cuda::CudaExec(device, host_threads));
}
}  // namespace seaspring::solver
