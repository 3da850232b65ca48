// SeaSpring — MIT licence.
/// \file part_test_util.h
/// \brief Tests of the part files and their writer: a scratch folder per test, byte-exact
///        comparison of arrays, and five particles whose values a converting writer would change.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

#include "part_particles.h"

namespace seaspring::test {

namespace fs = std::filesystem;

template <typename T>
inline bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// A fresh scratch folder per process and test (ctest runs test cases in parallel), removed
/// at the end of the test.
struct Scratch {
    std::string dir;
    Scratch() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = (fs::path(::testing::TempDir()) /
               ("seaspring_part_" + std::to_string(::getpid()) + "_" +
                info->test_suite_name() + "_" + info->name()))
                  .string();
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~Scratch() {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
};

using Particles = PartParticles;

/// Five particles whose values include bit patterns a converting writer would change:
/// -0, a NaN with a payload, infinities, subnormals and extremes.
inline Particles makeParticles() {
    const double dnan = std::nan("0x5a5a");
    const float fnan = std::nanf("0x2a");
    const double ddenorm = std::numeric_limits<double>::denorm_min();
    const float fdenorm = std::numeric_limits<float>::denorm_min();
    const float finf = std::numeric_limits<float>::infinity();
    Particles p;
    p.pos = {0.0, -0.0, 1.0 / 3.0,   1e-300, -2.5, 7.0,  dnan, ddenorm, -1e300,
             0.1, 0.2,  0.3,         -0.0,   1.0,  2.0};
    p.vel = {0.0f, -0.0f, 1.0f / 3.0f, fnan, finf, -finf, fdenorm, 3.4e38f, -1.5f,
             0.1f, 0.2f, 0.3f,         -7.25f, 0.0f, 1e-30f};
    p.rhop = {1000.0f, 999.875f, fnan, 1025.5f, -0.0f};
    p.press = {0.0f, -12.5f, finf, 1.0e5f, fdenorm};
    p.id = {0, 1, 2, 3, 0xFFFFFFFFu};
    p.type = {0, 1, 2, 3, 255};
    p.mk = {1, 12, 13, 14, 0xFFFF};
    p.excluded = {0, 0, 3, 1, 2};
    p.mass = {6.14125e-4f, 6.14125e-4f, 1.6e-3f, 6.0e-4f, fdenorm};  // walls, solid, fluid, odd
    p.constants = {0.0147224, 0.0085, "Wendland C2", 1000.0, 3, 162005.0};
    return p;
}

}  // namespace seaspring::test
