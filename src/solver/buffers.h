// SeaSpring — MIT licence.
/// \file buffers.h
/// \brief The container interface the backend-independent code (particle_store.h,
///        solid_arrays.h, engine.h) uses for arrays: `Buf<T>` is std::vector on the host
///        (HostExec) and cuda::DeviceBuffer on the GPU (CudaExec). A container provides
///        data(), size(), empty() and resize(n) (contents unspecified after a size change), and
///        the free functions below (assignFrom, fillZero, copyToHost, copyToHostBytes), found by
///        argument-dependent lookup; DeviceBuffer's are in cuda/device_buffer.cuh.
#pragma once

#include <cstring>
#include <vector>

namespace seaspring::solver {

template <typename T>
using HostBuffer = std::vector<T>;

/// dst = a copy of the host vector src (set-up; uploads on the GPU).
template <typename T>
void assignFrom(std::vector<T>& dst, const std::vector<T>& src) {
    dst = src;
}
/// dst = n value-initialised (all-zero) elements, without a host copy on the GPU (a memset there).
template <typename T>
void fillZero(std::vector<T>& dst, std::size_t n) {
    dst.assign(n, T{});
}
/// dst = the contents of src, on the host.
template <typename T>
void copyToHost(const std::vector<T>& src, std::vector<T>& dst) {
    dst = src;
}
/// The bytes of src into dst (src.size() * sizeof(T) bytes of host memory).
template <typename T>
void copyToHostBytes(const std::vector<T>& src, void* dst) {
    if (!src.empty()) std::memcpy(dst, src.data(), src.size() * sizeof(T));
}

}  // namespace seaspring::solver
