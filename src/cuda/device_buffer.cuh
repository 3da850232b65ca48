// SeaSpring — MIT licence.
/// \file device_buffer.cuh
/// \brief Owning device allocation (deviceAllocate / deviceFree of core/device_memory.h: the ledger
///        of the bytes held and the out-of-memory message), movable, not copyable.
#pragma once

#include <cuda_runtime.h>

#include <cstddef>
#include <cstring>
#include <utility>
#include <vector>

#include "cuda/cuda_check.cuh"
#include "core/device_memory.h"

namespace seaspring::cuda {

/// Uploads up to this many bytes go through pinned host memory and are queued on the stream
/// (cudaMemcpy from pageable memory would wait for the device: a host round trip per upload,
/// e.g. the moving boundaries' poses every step).
constexpr std::size_t kStagedUploadMax = 64 * 1024;

/// Pinned host staging for small uploads: the data is copied here and its transfer queued
/// (cudaMemcpyAsync); the next use waits for the previous transfer (an event), so the host
/// vector may change at once and the staging is never overwritten while it is read.
class PinnedStaging {
public:
    PinnedStaging() = default;
    ~PinnedStaging() {
        if (host_) cudaFreeHost(host_);
        if (done_) cudaEventDestroy(done_);
    }
    PinnedStaging(const PinnedStaging&) = delete;
    PinnedStaging& operator=(const PinnedStaging&) = delete;
    PinnedStaging(PinnedStaging&& o) noexcept { swap(o); }
    PinnedStaging& operator=(PinnedStaging&& o) noexcept {
        swap(o);
        return *this;
    }
    void upload(void* dst, const void* src, std::size_t bytes) {
        if (done_ == nullptr) SEASPRING_CUDA_CHECK(cudaEventCreateWithFlags(&done_, cudaEventDisableTiming));
        SEASPRING_CUDA_CHECK(cudaEventSynchronize(done_));  // the previous transfer has read the staging
        if (bytes > capacity_) {
            if (host_) SEASPRING_CUDA_CHECK(cudaFreeHost(host_));
            host_ = nullptr;
            SEASPRING_CUDA_CHECK(cudaMallocHost(&host_, bytes));
            capacity_ = bytes;
        }
        std::memcpy(host_, src, bytes);
        SEASPRING_CUDA_CHECK(cudaMemcpyAsync(dst, host_, bytes, cudaMemcpyHostToDevice));
        SEASPRING_CUDA_CHECK(cudaEventRecord(done_));
    }

private:
    void swap(PinnedStaging& o) noexcept {
        std::swap(host_, o.host_);
        std::swap(capacity_, o.capacity_);
        std::swap(done_, o.done_);
    }
    void* host_ = nullptr;
    std::size_t capacity_ = 0;
    cudaEvent_t done_ = nullptr;
};

template <typename T>
class DeviceBuffer {
public:
    DeviceBuffer() = default;
    explicit DeviceBuffer(std::size_t n) { resize(n); }
    ~DeviceBuffer() { release(); }
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;
    DeviceBuffer(DeviceBuffer&& o) noexcept : p_(o.p_), n_(o.n_), staging_(std::move(o.staging_)) {
        o.p_ = nullptr;
        o.n_ = 0;
    }
    DeviceBuffer& operator=(DeviceBuffer&& o) noexcept {
        std::swap(p_, o.p_);
        std::swap(n_, o.n_);
        std::swap(staging_, o.staging_);
        return *this;
    }
    /// Discards the contents.
    void resize(std::size_t n) {
        if (n == n_) return;
        release();
        if (n > 0) ::seaspring::deviceAllocate(reinterpret_cast<void**>(&p_), n * sizeof(T));
        n_ = n;
    }
    /// Small uploads are queued (PinnedStaging), larger ones wait for the device.
    void upload(const std::vector<T>& h) {
        resize(h.size());
        const std::size_t bytes = h.size() * sizeof(T);
        if (bytes == 0) return;
        if (bytes <= kStagedUploadMax) staging_.upload(p_, h.data(), bytes);
        else SEASPRING_CUDA_CHECK(cudaMemcpy(p_, h.data(), bytes, cudaMemcpyHostToDevice));
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
        ::seaspring::deviceFree(p_, n_ * sizeof(T));
        p_ = nullptr;
        n_ = 0;
    }
    T* p_ = nullptr;
    std::size_t n_ = 0;
    PinnedStaging staging_;
};

/// The container interface of solver::SolidArrays (found by argument-dependent lookup).
template <typename T>
void assignFrom(DeviceBuffer<T>& dst, const std::vector<T>& src) {
    dst.upload(src);
}
template <typename T>
void copyToHost(const DeviceBuffer<T>& src, std::vector<T>& dst) {
    src.download(dst);
}
/// dst = n all-zero elements (cudaMemset: the bits of T{} for the solver's field types, whose
/// zero is +0 in every member).
template <typename T>
void fillZero(DeviceBuffer<T>& dst, std::size_t n) {
    dst.resize(n);
    if (n > 0) SEASPRING_CUDA_CHECK(cudaMemset(dst.data(), 0, n * sizeof(T)));
}
/// The bytes of src into dst (src.size() * sizeof(T) bytes of host memory).
template <typename T>
void copyToHostBytes(const DeviceBuffer<T>& src, void* dst) {
    if (!src.empty()) SEASPRING_CUDA_CHECK(cudaMemcpy(dst, src.data(), src.size() * sizeof(T), cudaMemcpyDeviceToHost));
}

}  // namespace seaspring::cuda
