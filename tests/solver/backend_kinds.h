// SeaSpring — MIT licence.
/// \file backend_kinds.h
/// \brief The backends a typed test body runs on (OpenMP's one test body per platform): each
///        kind makes a Backend, or returns null with the reason (no GPU: the CUDA instances then
///        skip, visibly). Shared by the typed solver tests.
#pragma once

#include <cstdlib>
#include <memory>
#include <string>

#include "solver_test_util.h"

namespace seaspring::test {

/// OpenMP on 2 and 3 threads.
struct Cpu2 {
    static std::unique_ptr<solver::Backend> make(std::string&) { return solver::makeCpuBackend(2); }
};
struct Cpu3 {
    static std::unique_ptr<solver::Backend> make(std::string&) { return solver::makeCpuBackend(3); }
};
/// CUDA, device 0.
struct Gpu {
    static std::unique_ptr<solver::Backend> make(std::string& why) { return solver::makeCudaBackend(0, why); }
};
/// CUDA with kLanes bond lanes forced (SEASPRING_BOND_LANES) and, with kPerPass, the solids'
/// sub-cycle as one launch per pass whatever its size (SEASPRING_SOLID_BLOCK_MAX=0).
template <int kLanes, bool kPerPass = false>
struct GpuBondLanes {
    static std::unique_ptr<solver::Backend> make(std::string& why) {
        const std::string lanes = std::to_string(kLanes);
        setenv("SEASPRING_BOND_LANES", lanes.c_str(), 1);
        if (kPerPass) setenv("SEASPRING_SOLID_BLOCK_MAX", "0", 1);
        std::unique_ptr<solver::Backend> b = solver::makeCudaBackend(0, why);
        unsetenv("SEASPRING_BOND_LANES");
        if (kPerPass) unsetenv("SEASPRING_SOLID_BLOCK_MAX");
        return b;
    }
};

}  // namespace seaspring::test
