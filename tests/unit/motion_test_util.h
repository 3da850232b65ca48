// SeaSpring — MIT licence.
/// \file motion_test_util.h
/// \brief What the motion tests share (test_motion_player.cpp, test_rigid_transform.cpp): pi,
///        the tolerance of closed forms in double, and a vector comparison.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "core/vec3.h"

namespace seaspring::test::motion {

inline constexpr double kPi = 3.14159265358979323846;
/// Closed forms evaluated in double by two different routes agree to a few ulps of O(1) values.
inline constexpr double kTol = 1e-12;

inline void expectNear(const Vec3d& got, const Vec3d& want, double tol, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, tol) << what;
    EXPECT_NEAR(got.y, want.y, tol) << what;
    EXPECT_NEAR(got.z, want.z, tol) << what;
}

}  // namespace seaspring::test::motion
