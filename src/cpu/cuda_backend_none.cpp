// SeaSpring — MIT licence.
/// \file cuda_backend_none.cpp
/// \brief makeCudaBackend when SeaSpring is built without CUDA.
#include "solver/backend.h"

namespace seaspring::solver {
std::unique_ptr<Backend> makeCudaBackend(int, std::string& why, int) {
    why = "this seaspring was built without the CUDA backend (nvcc was not found at configure time)";
    return nullptr;
}
}  // namespace seaspring::solver
