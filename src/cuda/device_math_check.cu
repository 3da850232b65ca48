// SeaSpring — MIT licence.
/// \file device_math_check.cu
/// \brief deviceSqrtNormalRangeMismatches, deviceReciprocalNormalRangeMismatches: every float of a
///        range through the GPU's own form of an IEEE operation and through its definition on the
///        device, bits compared. A check, not a pass: the counts are integers gathered with
///        integer atomics.
#include <cuda_runtime.h>

#include "core/device_math_check.h"
#include "physics/sph_types.h"

namespace seaspring {
namespace {

enum class Op { Sqrt, Reciprocal };

/// The GPU's form of `op` (or its rough first approximation) and the definition it must match.
template <Op op>
__device__ void forms(float x, bool rough, float& got, float& want) {
    if (op == Op::Sqrt) {
        if (rough) {
            float r;
            asm("rsqrt.approx.ftz.f32 %0, %1;" : "=f"(r) : "f"(x));
            got = __fmul_rn(x, r);
        } else {
            got = physics::sqrtNormalRange(x);
        }
        want = sqrtf(x);
    } else {
        if (rough)
            asm("rcp.approx.ftz.f32 %0, %1;" : "=f"(got) : "f"(x));
        else
            got = physics::reciprocalNormalRange(x);
        want = physics::reciprocalNormalRangeSpec(x);
    }
}

template <Op op>
__global__ void mismatchKernel(std::uint32_t first, std::uint32_t last, bool rough,
                               unsigned long long* count, unsigned int* first_bad) {
    unsigned long long mine = 0;
    unsigned int bad = 0xffffffffu;
    const std::uint64_t n = std::uint64_t(last) - first + 1;
    const std::uint64_t stride = std::uint64_t(gridDim.x) * blockDim.x;
    for (std::uint64_t k = std::uint64_t(blockIdx.x) * blockDim.x + threadIdx.x; k < n; k += stride) {
        const std::uint32_t bits = first + std::uint32_t(k);
        const float x = __uint_as_float(bits);
        float got, want;
        forms<op>(x, rough, got, want);
        if (__float_as_uint(got) != __float_as_uint(want)) {
            ++mine;
            bad = bits < bad ? bits : bad;
        }
    }
    if (mine != 0) {
        atomicAdd(count, mine);
        atomicMin(first_bad, bad);
    }
}

template <Op op>
DeviceMathCheck mismatches(std::uint32_t first_bits, std::uint32_t last_bits, bool rough) {
    DeviceMathCheck r;
    int n = 0;
    if (cudaGetDeviceCount(&n) != cudaSuccess || n == 0) {
        cudaGetLastError();
        r.why = "no CUDA device";
        return r;
    }
    if (last_bits < first_bits) {
        r.why = "empty range";
        return r;
    }
    unsigned long long* count = nullptr;
    unsigned int* first_bad = nullptr;
    if (cudaMalloc(&count, sizeof *count) != cudaSuccess || cudaMalloc(&first_bad, sizeof *first_bad) != cudaSuccess) {
        r.why = "cudaMalloc failed";
        cudaFree(count);
        return r;
    }
    const unsigned long long zero = 0;
    const unsigned int none = 0xffffffffu;
    cudaMemcpy(count, &zero, sizeof zero, cudaMemcpyHostToDevice);
    cudaMemcpy(first_bad, &none, sizeof none, cudaMemcpyHostToDevice);
    mismatchKernel<op><<<4096, 256>>>(first_bits, last_bits, rough, count, first_bad);
    unsigned long long c = 0;
    unsigned int fb = 0;
    const cudaError_t err = cudaMemcpy(&c, count, sizeof c, cudaMemcpyDeviceToHost);
    cudaMemcpy(&fb, first_bad, sizeof fb, cudaMemcpyDeviceToHost);
    cudaFree(count);
    cudaFree(first_bad);
    if (err != cudaSuccess) {
        r.why = cudaGetErrorString(err);
        return r;
    }
    r.ran = true;
    r.checked = std::uint64_t(last_bits) - first_bits + 1;
    r.mismatches = c;
    r.first_mismatch_bits = c ? fb : 0u;
    return r;
}

}  // namespace

DeviceMathCheck deviceSqrtNormalRangeMismatches(std::uint32_t first_bits, std::uint32_t last_bits, bool rough) {
    return mismatches<Op::Sqrt>(first_bits, last_bits, rough);
}

DeviceMathCheck deviceReciprocalNormalRangeMismatches(std::uint32_t first_bits, std::uint32_t last_bits, bool rough) {
    return mismatches<Op::Reciprocal>(first_bits, last_bits, rough);
}

}  // namespace seaspring
