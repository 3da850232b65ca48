// SeaSpring — MIT licence.
/// \file cuda_gauges.cuh
/// \brief CUDA driver of the gauge measurements (physics/gauges.h): one thread per gauge point,
///        per maxz row and per boundary particle (positions of the wanted ids), over the sorted
///        device arrays; only the small answers travel to the host.
#pragma once

#include <cstdint>

#include "cuda/cuda_arrays.cuh"
#include "cuda/device_buffer.cuh"
#include "physics/gauges.h"
#include "solver/backend.h"

namespace seaspring::cuda {

class CudaGauges {
public:
    /// Uploads the queries of the run (gauge points, maxz rows, wanted ids of the boundary block).
    void set(const solver::GaugeQueries& q, std::uint32_t nbound);
    /// Answers them for the current sorted state.
    void evaluate(const solver::PhysicsChoice& choice, const DeviceArrays& a, std::uint32_t nbound,
                  const physics::FluidConstants& c, const physics::CellGrid& g, solver::GaugeResults& out);

private:
    DeviceBuffer<physics::Float4> points_;
    DeviceBuffer<physics::MaxzRow> rows_;
    DeviceBuffer<std::uint32_t> slot_of_id_;
    DeviceBuffer<physics::GaugeSample> samples_;
    DeviceBuffer<double> maxz_;
    DeviceBuffer<physics::Double3> positions_;
    std::size_t nids_ = 0;
};

}  // namespace seaspring::cuda
