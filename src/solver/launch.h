// SeaSpring — MIT licence.
/// \file launch.h
/// \brief How a pass is spread over threads, per execution policy: GPU threads per block and
///        the CPU's OpenMP schedule (chunk 0: static; > 0: dynamic with that chunk). Only speed
///        depends on these: every pass writes each index's own entries, so any split gives the
///        same bits.
#pragma once

namespace seaspring::solver {

/// Light per-particle passes (sort keys, gathers, integration, cell ranges).
struct LaunchDefault {
    static constexpr int kGpuThreads = 256;
    static constexpr int kCpuChunk = 0;
};
/// The fluid particles' pair loops (uneven work per particle).
struct LaunchFluidPairs {
    static constexpr int kGpuThreads = 128;
    static constexpr int kCpuChunk = 256;
};
/// The boundary particles' pair loops (dry walls finish at once).
struct LaunchBoundPairs {
    static constexpr int kGpuThreads = 128;
    static constexpr int kCpuChunk = 512;
};
/// The hydrodynamic force on boundary or solid particles.
struct LaunchHydro {
    static constexpr int kGpuThreads = 128;
    static constexpr int kCpuChunk = 64;
};
/// Gauge points.
struct LaunchGauges {
    static constexpr int kGpuThreads = 128;
    static constexpr int kCpuChunk = 0;
};

}  // namespace seaspring::solver
