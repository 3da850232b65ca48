// SeaSpring — MIT licence.
/// \file cpu_backend.cpp
/// \brief The OpenMP backend: the engine (solver/engine.h) over the host execution policy.
#include <fstream>
#include <memory>
#include <string>

#include "cpu/host_exec.h"
#include "solver/engine.h"

namespace seaspring::cpu {

std::string HostExec::deviceName() const {
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) return line.substr(colon + 2);
        }
    return "unknown CPU";
}

}  // namespace seaspring::cpu

namespace seaspring::solver {
std::unique_ptr<Backend> makeCpuBackend(int threads) {
    return std::make_unique<Engine<cpu::HostExec>>(cpu::HostExec(threads));
}
}  // namespace seaspring::solver
