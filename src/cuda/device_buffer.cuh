// SeaSpring — MIT licence.
/// \file device_buffer.cuh
/// \brief Owning device allocation (cudaMalloc / cudaFree), movable, not copyable.
#pragma once

#include <cuda_runtime.h>

#include <cstddef>
#include <utility>
#include <vector>

#include "cuda/cuda_check.cuh"

namespace seaspring::cuda {

template <typename T>
class DeviceBuffer {
public:
    DeviceBuffer() = default;
    explicit DeviceBuffer(std::size_t n) { resize(n); }
    ~DeviceBuffer() { release(); }
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;
    DeviceBuffer(DeviceBuffer&& o) noexcept : p_(o.p_), n_(o.n_) { o.p_ = nullptr; o.n_ = 0; }
    DeviceBuffer& operator=(DeviceBuffer&& o) noexcept {
        std::swap(p_, o.p_);
        std::swap(n_, o.n_);
        return *this;
    }
    /// Discards the contents.
    void resize(std::size_t n) {
        if (n == n_) return;
        release();
        if (n > 0) SEASPRING_CUDA_CHECK(cudaMalloc(&p_, n * sizeof(T)));
        n_ = n;
    }
    void upload(const std::vector<T>& h) {
        resize(h.size());
        if (!h.empty()) SEASPRING_CUDA_CHECK(cudaMemcpy(p_, h.data(), h.size() * sizeof(T), cudaMemcpyHostToDevice));
    }
    void download(std::vector<T>& h) const {
        h.resize(n_);
        if (n_ > 0) SEASPRING_CUDA_CHECK(cudaMemcpy(h.data(), p_, n_ * sizeof(T), cudaMemcpyDeviceToHost));
    }
    T* data() const { return p_; }
    std::size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }

private:
    void release() {
        if (p_) cudaFree(p_);
        p_ = nullptr;
        n_ = 0;
    }
    T* p_ = nullptr;
    std::size_t n_ = 0;
};

/// The container interface of solver::SolidArrays (found by argument-dependent lookup).
template <typename T>
void assignFrom(DeviceBuffer<T>& dst, const std::vector<T>& src) {
    dst.upload(src);
}
/// Device-to-device copy, queued on the default stream.
template <typename T>
void copyBuffer(DeviceBuffer<T>& dst, const DeviceBuffer<T>& src) {
    dst.resize(src.size());
    if (!src.empty())
        SEASPRING_CUDA_CHECK(cudaMemcpyAsync(dst.data(), src.data(), src.size() * sizeof(T), cudaMemcpyDeviceToDevice));
}
template <typename T>
void copyToHost(const DeviceBuffer<T>& src, std::vector<T>& dst) {
    src.download(dst);
}

}  // namespace seaspring::cuda
