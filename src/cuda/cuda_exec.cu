// SeaSpring — MIT licence.
/// \file cuda_exec.cu
/// \brief The non-template parts of the CUDA execution policy (cuda_exec.cuh).
#include "cuda/cuda_exec.cuh"

#include <cub/device/device_merge.cuh>
#include <cub/device/device_partition.cuh>

#include <cstring>

#include "core/device_memory.h"
#include <stdexcept>
#include <string>
#include <thread>

namespace seaspring::cuda {

__global__ void lowerBoundKernel(std::uint32_t b, std::uint32_t e, const std::uint64_t* keys, std::uint64_t value,
                                 std::uint32_t* out) {
    std::uint32_t lo = b, hi = e;
    while (lo < hi) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        if (keys[mid] < value) lo = mid + 1;
        else hi = mid;
    }
    *out = lo;
}

__global__ void stayerKeysKernel(std::uint32_t b, std::uint32_t e, const std::uint64_t* keys,
                                 const std::uint32_t* perm_out, std::uint64_t* keys_out, std::uint64_t at_least,
                                 std::uint32_t* words) {
    const std::uint32_t i = b + blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= e) return;
    const std::uint64_t k = keys[perm_out[i]];
    keys_out[i] = k;
    if (i > b && i - b < words[0] && keys[perm_out[i - 1]] >= k) words[1] = 1u;  // any writer writes 1
    if (k >= at_least) atomicAdd(words + 2, 1u);
}

DeviceMemoryUse CudaExec::deviceMemory() const {
    DeviceMemoryUse m;
    m.held = deviceBytesHeld();
    m.peak = deviceBytesPeak();
    std::size_t free_bytes = 0, total_bytes = 0;
    if (cudaMemGetInfo(&free_bytes, &total_bytes) == cudaSuccess) m.total = total_bytes;
    return m;
}

namespace {
/// SEASPRING_SOLID_BLOCK_MAX from the environment (a non-negative integer), else the default.
std::uint32_t blockMaxFromEnv() {
    const char* env = std::getenv("SEASPRING_SOLID_BLOCK_MAX");
    if (env == nullptr || *env == '\0') return kSequenceBlockMaxDefault;
    char* end = nullptr;
    const unsigned long v = std::strtoul(env, &end, 10);
    return (*end == '\0') ? std::uint32_t(std::min<unsigned long>(v, 0xffffffffUL)) : kSequenceBlockMaxDefault;
}

/// log2 of SEASPRING_BOND_LANES (1, 2, 4 or 8) from the environment, else -1 (the rule).
int bondLaneShiftFromEnv() {
    const char* env = std::getenv("SEASPRING_BOND_LANES");
    if (env == nullptr || *env == '\0') return -1;
    for (std::uint32_t s = 0; s <= kMaxBondLaneShift; ++s)
        if (std::strcmp(env, std::to_string(1u << s).c_str()) == 0) return int(s);
    return -1;
}
}  // namespace

CudaExec::CudaExec(int device, int host_threads) {
    const unsigned cores = std::thread::hardware_concurrency();
    host_threads_ = host_threads > 0 ? host_threads : (cores > 0 ? int(cores) : 1);
    SEASPRING_CUDA_CHECK(cudaSetDevice(device));
    resetDevicePeak();  // the run's peak is its own (core/device_memory.h)
    cudaDeviceProp prop{};
    SEASPRING_CUDA_CHECK(cudaGetDeviceProperties(&prop, device));
    name_ = prop.name;
    reduce_blocks_ = std::uint32_t(prop.multiProcessorCount) * 4u;
    block_max_ = blockMaxFromEnv();
    bond_lane_shift_ = bondLaneShiftFromEnv();
    lower_bound_.resize(1);
    stayers_.resize(3);
    reduce_done_.resize(1);
    SEASPRING_CUDA_CHECK(cudaMemset(reduce_done_.data(), 0, sizeof(unsigned)));
    void* pinned = nullptr;
    SEASPRING_CUDA_CHECK(cudaMallocHost(&pinned, kReadbackBytes));
    readback_.reset(pinned);
}

void CudaExec::prepareSort(std::size_t n) {
    // The scratch of the largest of the radix sort, the partition and the merge (size queries
    // read no buffer).
    std::size_t temp = 0, part = 0, merge = 0;
    cub::DoubleBuffer<std::uint64_t> k(nullptr, nullptr);
    cub::DoubleBuffer<std::uint32_t> p(nullptr, nullptr);
    SEASPRING_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, temp, k, p, int(n)));
    SEASPRING_CUDA_CHECK(cub::DevicePartition::Flagged(nullptr, part, static_cast<const std::uint32_t*>(nullptr),
                                                       static_cast<const std::uint8_t*>(nullptr),
                                                       static_cast<std::uint32_t*>(nullptr),
                                                       static_cast<std::uint32_t*>(nullptr), int(n)));
    const std::uint64_t* kin = nullptr;
    const std::uint32_t* pin = nullptr;
    SEASPRING_CUDA_CHECK(cub::DeviceMerge::MergePairs(nullptr, merge, kin, pin, std::int64_t(n), kin, pin, std::int64_t(n),
                                                      static_cast<std::uint64_t*>(nullptr),
                                                      static_cast<std::uint32_t*>(nullptr)));
    temp = std::max({temp, part, merge, std::size_t(1)});
    sort_temp_.resize(temp);
}

void CudaExec::ungated(const char* what) const {
    if (gate_ != nullptr) throw std::logic_error(std::string("CudaExec: ") + what + " launched under a gate");
}

void CudaExec::sortPairs(std::uint64_t* keys, std::uint64_t* keys_alt, std::uint32_t* perm, std::uint32_t* perm_alt,
                         std::uint32_t b, std::uint32_t e) const {
    ungated("sortPairs");
    if (e <= b) return;
    std::size_t temp = sort_temp_.size();
    cub::DoubleBuffer<std::uint64_t> k(keys + b, keys_alt + b);
    cub::DoubleBuffer<std::uint32_t> p(perm + b, perm_alt + b);
    SEASPRING_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(sort_temp_.data(), temp, k, p, int(e - b)));
    if (k.Current() != keys + b) copy(keys + b, k.Current(), e - b);
    if (p.Current() != perm + b) copy(perm + b, p.Current(), e - b);
}

std::uint32_t CudaExec::stayersFirst(const std::uint64_t* keys, const std::uint32_t* perm, const std::uint8_t* stays,
                                     std::uint64_t* keys_out, std::uint32_t* perm_out, std::uint32_t b, std::uint32_t e,
                                     std::uint64_t at_least, std::uint32_t& n_at_least) const {
    ungated("stayersFirst");
    n_at_least = 0;
    if (e <= b) return 0;
    std::size_t temp = sort_temp_.size();
    std::uint32_t* words = stayers_.data();
    SEASPRING_CUDA_CHECK(cudaMemsetAsync(words, 0, 3 * sizeof(std::uint32_t)));
    SEASPRING_CUDA_CHECK(cub::DevicePartition::Flagged(sort_temp_.data(), temp, perm + b, stays + b, perm_out + b, words,
                                                       int(e - b)));
    constexpr unsigned kThreads = 256;
    stayerKeysKernel<<<(e - b + kThreads - 1) / kThreads, kThreads>>>(b, e, keys, perm_out, keys_out, at_least, words);
    SEASPRING_CUDA_LAUNCH_CHECK();
    SEASPRING_CUDA_CHECK(cudaMemcpyAsync(readback_.get(), words, 3 * sizeof(std::uint32_t), cudaMemcpyDeviceToHost));
    SEASPRING_CUDA_CHECK(cudaStreamSynchronize(0));
    std::uint32_t w[3];
    std::memcpy(w, readback_.get(), sizeof w);
    n_at_least = w[2];
    return w[1] != 0 ? 0u : w[0];
}

void CudaExec::mergePairs(const std::uint64_t* keys, const std::uint32_t* perm, std::uint32_t b, std::uint32_t m,
                          std::uint32_t e, std::uint64_t* keys_out, std::uint32_t* perm_out) const {
    ungated("mergePairs");
    if (e <= b) return;
    std::size_t need = 0;
    SEASPRING_CUDA_CHECK(cub::DeviceMerge::MergePairs(nullptr, need, keys + b, perm + b, std::int64_t(m - b), keys + m,
                                                      perm + m, std::int64_t(e - m), keys_out + b, perm_out + b));
    if (need > sort_temp_.size()) sort_temp_.resize(need);  // prepareSort sized it for the largest case
    SEASPRING_CUDA_CHECK(cub::DeviceMerge::MergePairs(sort_temp_.data(), need, keys + b, perm + b, std::int64_t(m - b),
                                                      keys + m, perm + m, std::int64_t(e - m), keys_out + b, perm_out + b));
}

std::uint32_t CudaExec::lowerBound(const std::uint64_t* keys, std::uint32_t b, std::uint32_t e,
                                   std::uint64_t value) const {
    ungated("lowerBound");
    if (e <= b) return b;
    lowerBoundKernel<<<1, 1>>>(b, e, keys, value, lower_bound_.data());
    SEASPRING_CUDA_LAUNCH_CHECK();
    SEASPRING_CUDA_CHECK(cudaMemcpyAsync(readback_.get(), lower_bound_.data(), sizeof(std::uint32_t), cudaMemcpyDeviceToHost));
    SEASPRING_CUDA_CHECK(cudaStreamSynchronize(0));
    std::uint32_t r = b;
    std::memcpy(&r, readback_.get(), sizeof r);
    return r;
}

}  // namespace seaspring::cuda
