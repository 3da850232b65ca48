// SeaSpring — MIT licence.
/// \file test_rigid_transform.cpp
/// \brief The motion player's rigid transforms: composition order, and rotations about an axis
///        against hand-computed points with DualSPHysics' sign, orthonormal with the axis fixed,
///        and a degenerate axis rejected. The movements themselves: test_motion_player.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "motion_test_util.h"
#include "solver/motion_player.h"

using namespace seaspring;
using namespace seaspring::solver;
using namespace seaspring::test::motion;

namespace {

double det3(const RigidTransform& tr) {
    const auto& r = tr.r;
    return r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
           r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
           r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
}

}  // namespace

// ---------------------------------------------------------------- transforms and rotations

TEST(RigidTransform, IdentityAndComposeOrder) {
    const RigidTransform id = RigidTransform::identity();
    expectNear(id.apply({1.5, -2, 3}), {1.5, -2, 3}, 0, "identity");
    // first: +90 deg (DS sign) about the z axis through the origin; second: shift by (10,0,0).
    const RigidTransform rot = axisRotation({0, 0, 0}, {0, 0, 1}, kPi / 2);
    RigidTransform move = RigidTransform::identity();
    move.t[0] = 10;
    // (1,0,0) -rot-> (0,-1,0) -move-> (10,-1,0)
    expectNear(compose(rot, move).apply({1, 0, 0}), {10, -1, 0}, kTol, "rot then move");
    // (1,0,0) -move-> (11,0,0) -rot-> (0,-11,0)
    expectNear(compose(move, rot).apply({1, 0, 0}), {0, -11, 0}, kTol, "move then rot");
}

TEST(AxisRotation, NinetyDegreesMapsHandComputedPointsWithTheDualSphysicsSign) {
    // DS (JMatrix4::MatrixRot): right-handed about p1 - p2. About +z: x -> -y, y -> x.
    const RigidTransform z = axisRotation({0, 0, 0}, {0, 0, 1}, kPi / 2);
    expectNear(z.apply({1, 0, 0}), {0, -1, 0}, kTol, "z: x");
    expectNear(z.apply({0, 1, 0}), {1, 0, 0}, kTol, "z: y");
    expectNear(z.apply({0, 0, 2}), {0, 0, 2}, kTol, "z: on the axis");
    // Reversing the axis reverses the sense.
    const RigidTransform zr = axisRotation({0, 0, 1}, {0, 0, 0}, kPi / 2);
    expectNear(zr.apply({1, 0, 0}), {0, 1, 0}, kTol, "-z: x");
    // About +y (the 2D rolling-tank axis): +x is lifted towards +z, +z goes to -x.
    const RigidTransform y = axisRotation({0, -1, 0}, {0, 2, 0}, kPi / 2);
    expectNear(y.apply({1, 0, 0}), {0, 0, 1}, kTol, "y: x");
    expectNear(y.apply({0, 0, 1}), {-1, 0, 0}, kTol, "y: z");
    // About +x: y -> -z.
    const RigidTransform x = axisRotation({0, 0, 0}, {3, 0, 0}, kPi / 2);
    expectNear(x.apply({0, 1, 0}), {0, 0, -1}, kTol, "x: y");
    // An axis off the origin: parallel to z through (1,2,*).
    const RigidTransform off = axisRotation({1, 2, 0}, {1, 2, 5}, kPi / 2);
    expectNear(off.apply({2, 2, 0}), {1, 1, 0}, kTol, "offset: +x of the axis");
    expectNear(off.apply({1, 3, 7}), {2, 2, 7}, kTol, "offset: +y of the axis");
    expectNear(off.apply({1, 2, 3}), {1, 2, 3}, kTol, "offset: on the axis");
    // 180 deg about the diagonal (1,1,0): x <-> y, z -> -z (either sense).
    const RigidTransform d = axisRotation({0, 0, 0}, {1, 1, 0}, kPi);
    expectNear(d.apply({1, 0, 0}), {0, 1, 0}, kTol, "diagonal: x");
    expectNear(d.apply({0, 0, 1}), {0, 0, -1}, kTol, "diagonal: z");
}

TEST(AxisRotation, MatrixIsOrthonormalAndTheAxisStaysFixed) {
    const Vec3d axes[][2] = {{{0.3, -1.2, 2.0}, {1.1, 0.4, -0.7}},
                             {{5, 5, 5}, {5, 5, 6}},
                             {{-2, 0.5, 0}, {-2.5, 0.5, 0}},
                             {{0.3045, -0.01, 0}, {0.3045, 0.02, 0}}};
    for (const auto& ax : axes) {
        for (double angle : {-7.3, -kPi, -0.4, 1e-9, 0.25, 1.0, kPi / 3, 4.0, 100.0}) {
            const RigidTransform tr = axisRotation(ax[0], ax[1], angle);
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) {
                    const double rrt = tr.r[i][0] * tr.r[j][0] + tr.r[i][1] * tr.r[j][1] +
                                       tr.r[i][2] * tr.r[j][2];
                    EXPECT_NEAR(rrt, i == j ? 1.0 : 0.0, 1e-14) << "R R^T " << i << j;
                }
            }
            EXPECT_NEAR(det3(tr), 1.0, 1e-14);
            const Vec3d dir = ax[1] - ax[0];
            for (double s : {0.0, 1.0, 0.5, -2.0, 3.5}) {
                const Vec3d p = ax[0] + s * dir;
                expectNear(tr.apply(p), p, 1e-13, "point on the axis");
            }
            // Rotation by the angle about the reversed axis undoes it.
            const RigidTransform back = compose(tr, axisRotation(ax[1], ax[0], angle));
            expectNear(back.apply({1.7, -0.2, 0.9}), {1.7, -0.2, 0.9}, 1e-12, "inverse");
        }
    }
}

TEST(AxisRotation, RejectsADegenerateAxis) {
    EXPECT_THROW(axisRotation({1, 2, 3}, {1, 2, 3}, 0.5), Error);
}
