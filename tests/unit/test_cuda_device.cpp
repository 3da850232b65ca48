// SeaSpring — MIT licence.
/// \file test_cuda_device.cpp
/// \brief The CUDA device query, and the device's own forms of IEEE operations against them
///        (core/device_math_check.h). Skips, saying why, on machines without a GPU or without
///        the CUDA backend; on a GPU machine it checks the device is a Hopper (sm_90) build target.
#include <gtest/gtest.h>

#include <ios>

#include "core/device_info.h"
#include "core/device_math_check.h"
#include "core/device_memory.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "physics/sph_kernels.h"
#include "physics/sph_types.h"

TEST(CudaDevice, QueryReportsDevicesOrWhyNot) {
    std::string why;
    const auto devices = seaspring::listCudaDevices(&why);
    if (devices.empty()) {
        EXPECT_FALSE(why.empty());
        GTEST_SKIP() << "no CUDA device: " << why;
    }
    EXPECT_TRUE(seaspring::cudaBackendBuilt());
    for (const auto& d : devices) {
        EXPECT_FALSE(d.name.empty());
        EXPECT_GT(d.memory_gib, 1.0);
        // The build targets compute capability 9.0 (H100/H200).
        EXPECT_GE(d.major, 9) << d.name << " is sm_" << d.major << d.minor;
    }
}

// The message an allocation that does not fit stops with: what was asked, what SeaSpring held,
// what the device had, and what to change (MiB with one decimal).
TEST(DeviceMemory, OutOfMemoryMessageSaysWhatToChange) {
    const std::uint64_t mib = 1024u * 1024u;
    EXPECT_EQ(seaspring::outOfDeviceMemoryMessage(3 * mib + mib / 2, 5 * mib, 7 * mib, 11 * mib),
              "out of GPU memory: SeaSpring asked for 3.5 MiB more while its arrays held 5.0 MiB; the device had "
              "7.0 MiB free of 11.0 MiB (the CUDA context and other processes hold the rest); generate the case "
              "with a larger dp, free the GPU, or run on the CPU (-cpu)");
}

// The device ledger counts bytes: an allocation adds its bytes to the held and the peak, a free
// takes them off; a request larger than the device fails with the message above, leaves the
// ledger as it was and the device usable. A build without CUDA refuses every allocation.
TEST(DeviceMemory, LedgerCountsBytesAndATooLargeRequestSaysWhatToChange) {
    using namespace seaspring;
    const std::uint64_t mib = 1024u * 1024u;
    void* p = nullptr;
    if (!cudaBackendBuilt()) {
        try {
            deviceAllocate(&p, mib);
            ADD_FAILURE() << "a build without CUDA allocated device memory";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("this build has no CUDA backend"), std::string::npos) << e.what();
        }
        GTEST_SKIP() << "no CUDA backend in this build (the refusal was checked)";
    }
    std::string why;
    if (listCudaDevices(&why).empty()) GTEST_SKIP() << "no CUDA device: " << why;
    const std::uint64_t held0 = deviceBytesHeld();
    resetDevicePeak();
    deviceAllocate(&p, 3 * mib);
    EXPECT_EQ(deviceBytesHeld(), held0 + 3 * mib);
    EXPECT_EQ(deviceBytesPeak(), held0 + 3 * mib);
    void* huge = nullptr;
    const std::uint64_t pib = mib * mib * 1024u;  // 2^50 bytes: no GPU has that
    try {
        deviceAllocate(&huge, std::size_t(pib));
        ADD_FAILURE() << "a 1 PiB device allocation succeeded";
        deviceFree(huge, std::size_t(pib));
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("out of GPU memory: SeaSpring asked for 1073741824.0 MiB more while its arrays held ", 0), 0u)
            << m;
        EXPECT_NE(m.find("generate the case with a larger dp"), std::string::npos) << m;
    }
    EXPECT_EQ(deviceBytesHeld(), held0 + 3 * mib);
    void* q = nullptr;
    deviceAllocate(&q, mib);  // the failure left the device usable
    EXPECT_EQ(deviceBytesPeak(), held0 + 4 * mib);
    deviceFree(q, mib);
    deviceFree(p, 3 * mib);
    EXPECT_EQ(deviceBytesHeld(), held0);
    EXPECT_EQ(deviceBytesPeak(), held0 + 4 * mib);
}

// physics::sqrtNormalRange is the fast path of the GPU's IEEE square root without its range
// check: every float of its range, about 1.9 billion, through it and through sqrtf on the device,
// bit for bit. The control (x * rsqrt(x), the first approximation) must differ somewhere, or the
// comparison could not see a difference. A neighbour pair's r^2 lies inside the range.
TEST(DeviceMath, SqrtNormalRangeIsSqrtfForEveryFloatInRange) {
    using namespace seaspring::physics;
    static_assert(kAlmostZero >= kSqrtNormalRangeMin, "a neighbour's r^2 is inside sqrtNormalRange's range");
    const std::uint32_t first = floatBitsToUint(kSqrtNormalRangeMin);
    const std::uint32_t last = floatBitsToUint(kSqrtNormalRangeEnd) - 1u;
    EXPECT_EQ(first, 0x0d800000u);  // 2^-100
    EXPECT_EQ(last, 0x7e7fffffu);   // just below 2^126
    const seaspring::DeviceMathCheck control = seaspring::deviceSqrtNormalRangeMismatches(first, last, true);
    if (!control.ran) GTEST_SKIP() << "no device check: " << control.why;
    EXPECT_GT(control.mismatches, control.checked / 100) << "the control x * rsqrt(x) should differ from sqrtf";
    const seaspring::DeviceMathCheck r = seaspring::deviceSqrtNormalRangeMismatches(first, last);
    ASSERT_TRUE(r.ran) << r.why;
    EXPECT_EQ(r.checked, std::uint64_t(last - first) + 1u);
    EXPECT_EQ(r.mismatches, 0u) << "first at bits 0x" << std::hex << r.first_mismatch_bits;
}

// physics::reciprocalNormalRange is the fast path of the GPU's IEEE reciprocal without its range
// check: all 2^32 floats (both signs, zeros, subnormals, infinities, NaNs) through it and through
// its definition reciprocalNormalRangeSpec (1.f / x in [2^-126, 2^126], +-0 above, NaN below and
// for infinities and NaNs) on the device, bit for bit. The control (MUFU.RCP's approximation
// alone) must differ somewhere. The pair loops' arguments lie inside the range.
TEST(DeviceMath, ReciprocalNormalRangeIsItsDefinitionForEveryFloat) {
    using namespace seaspring::physics;
    EXPECT_EQ(floatBitsToUint(kReciprocalNormalRangeMin), 0x00800000u);  // 2^-126
    EXPECT_EQ(floatBitsToUint(kReciprocalNormalRangeMax), 0x7e800000u);  // 2^126
    const seaspring::DeviceMathCheck control = seaspring::deviceReciprocalNormalRangeMismatches(0u, 0xffffffffu, true);
    if (!control.ran) GTEST_SKIP() << "no device check: " << control.why;
    EXPECT_GT(control.mismatches, control.checked / 100) << "the control rcp.approx should differ from 1/x";
    const seaspring::DeviceMathCheck r = seaspring::deviceReciprocalNormalRangeMismatches(0u, 0xffffffffu);
    ASSERT_TRUE(r.ran) << r.why;
    EXPECT_EQ(r.checked, std::uint64_t(1) << 32);
    EXPECT_EQ(r.mismatches, 0u) << "first at bits 0x" << std::hex << r.first_mismatch_bits;
}

// The host's reciprocalNormalRange is its definition: 1/x inside the range, the GPU sequence's
// zeros and NaN outside it (checked against the GPU above).
TEST(HostMath, ReciprocalNormalRangeOutsideItsRange) {
    using namespace seaspring::physics;
    EXPECT_EQ(reciprocalNormalRange(4.f), 0.25f);
    EXPECT_EQ(reciprocalNormalRange(-kReciprocalNormalRangeMin), -1.f / kReciprocalNormalRangeMin);
    EXPECT_EQ(reciprocalNormalRange(kReciprocalNormalRangeMax), 1.f / kReciprocalNormalRangeMax);
    EXPECT_EQ(floatBitsToUint(reciprocalNormalRange(3e38f)), 0u);            // +0
    EXPECT_EQ(floatBitsToUint(reciprocalNormalRange(-3e38f)), 0x80000000u);  // -0
    for (float x : {0.f, -0.f, 1e-39f, -1e-40f, INFINITY, -INFINITY, NAN})
        EXPECT_EQ(floatBitsToUint(reciprocalNormalRange(x)), 0x7fffffffu) << x;
}
