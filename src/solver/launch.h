// SeaSpring — MIT licence.
/// \file launch.h
/// \brief How a pass is spread over threads, per execution policy: GPU threads per block (and,
///        optionally, kGpuBoundThreads: the block size its kernel is compiled for) and
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
/// Passes whose items are the lanes of a warp-wide group (RowExtentsPass with a warp per row: on the GPU every
/// thread of a warp takes part, so the launch's blocks are whole warps from index 0); the host
/// runs them with one lane per item.
struct LaunchRowLanes {
    static constexpr int kGpuThreads = LaunchDefault::kGpuThreads;
    static constexpr int kCpuChunk = 64;
};
/// The fluid particles' pair loops (uneven work per particle). Blocks of 64 threads, compiled
/// for 128 (kGpuBoundThreads: the registers and code of blocks of 128): a block's slot on an SM
/// is free once its two warps are done, not four, so more warps stay resident (NVIDIA H200,
/// same hashes: SPHERIC 4.36 M 0.985, 13.29 M 0.987, laminar+SPS 0.985, FlexStruc Liao 3D
/// 0.987 of blocks of 128; blocks of 32 and 96 lost on some; docs/performance-large.md).
struct LaunchFluidPairs {
    static constexpr int kGpuThreads = 64;
    static constexpr int kGpuBoundThreads = 128;
    static constexpr int kCpuChunk = 256;
};
/// The boundary particles' pair loops (dry walls finish at once); one launch with the fluid
/// particles' (CudaExec::forEachIndependent), so the same blocks.
struct LaunchBoundPairs {
    static constexpr int kGpuThreads = LaunchFluidPairs::kGpuThreads;
    static constexpr int kGpuBoundThreads = LaunchFluidPairs::kGpuBoundThreads;
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
