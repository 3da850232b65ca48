// SeaSpring — MIT licence.
/// \file test_solid_stability.cpp
/// \brief The corrected lattice's sub-step factor (solver::correctedSubStepScales, Gershgorin's
///        bound against the plain bulk lattice) against the exact ratio of the largest
///        eigenvalues of the stiffness matrices, found by power iteration with the solver's own
///        force functions (central differences of physics::solidSumAt, clampSumAt and
///        solidBondForceAt at the rest state; clamp nodes held).
///
/// The exact ratio here takes the same body with the plain lattice as the reference. For a
/// body 8 particles thick its largest eigenvalue is about the bulk lattice's, which VcpmDtCoef
/// is calibrated for, and the two factors must agree: within 1.5% (measured on the 2D
/// cantilever, nu 0.3975: Gershgorin 0.8554, exact 0.8637, 0.96% apart; the Antoci gate at its
/// finest resolution, 8 particles thick: 0.854 and 0.858). For thinner bodies a plain body is
/// softer than the bulk, so this reference is then the conservative one; the test prints the
/// figures at 4 and 2 particles through the thickness (cantilever: 0.8554 against 0.8308, and
/// 0.8688 against 0.7006; against the bulk the 2-particle factor would be near 0.76, so
/// Gershgorin's factor is some 14% above the exact one there: noted in docs/vcpm.md, not yet
/// corrected).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "physics/vcpm.h"
#include "solver/solid_arrays.h"
#include "solver/solid_setup.h"
#include "solver/solid_stability.h"
#include "solver/solver_case.h"
#include "solver_test_util.h"

using namespace seaspring;
using physics::Double3;

namespace {

/// The bond forces of every solid particle at positions x (the solver's pass functions, in
/// their order: sums, clamp sums, forces).
void bondForces(solver::SolidArrays<solver::HostBuffer>& a, const std::vector<Double3>& x, std::vector<Double3>& f) {
    a.pos = x;
    physics::SolidState st = a.state();
    const physics::SolidBonds b = a.bonds();
    physics::ClampNodes cn = a.clamps();
    for (std::uint32_t s = 0; s < b.n; ++s) st.sum[s] = physics::solidSumAt(s, st.pos, st, b, cn, 0.0);
    for (std::uint32_t c = 0; c < cn.n; ++c) cn.sum[c] = physics::clampSumAt(c, st.pos, st, b, cn, 0.0);
    f.resize(b.n);
    for (std::uint32_t s = 0; s < b.n; ++s) f[s] = physics::solidBondForceAt(s, st.pos, st, b, cn, 0.0);
}

/// The largest eigenvalue of the stiffness matrix K = -dF/dx at the rest state: power iteration
/// (300 products, K u by central differences of bondForces), the last Rayleigh quotient.
double largestStiffness(const solver::SolidSetup& s) {
    solver::SolidArrays<solver::HostBuffer> a;
    a.init(s);
    const std::uint32_t n = s.nsolid;
    std::mt19937 rng(12345);
    std::vector<Double3> u(n), xp(n), xm(n), fp, fm;
    auto draw = [&] { return double(rng()) / 4294967296.0 - 0.5; };
    for (Double3& v : u) v = Double3{draw(), s.dim == 3 ? draw() : 0.0, draw()};
    const double eps = 1e-7 * s.rest[0];
    double lambda = 0;
    for (int it = 0; it < 300; ++it) {
        double norm = 0;
        for (const Double3& v : u) norm += v.x * v.x + v.y * v.y + v.z * v.z;
        norm = std::sqrt(norm);
        for (std::uint32_t i = 0; i < n; ++i) {
            u[i] = Double3{u[i].x / norm, u[i].y / norm, u[i].z / norm};
            xp[i] = Double3{s.pos[i].x + eps * u[i].x, s.pos[i].y + eps * u[i].y, s.pos[i].z + eps * u[i].z};
            xm[i] = Double3{s.pos[i].x - eps * u[i].x, s.pos[i].y - eps * u[i].y, s.pos[i].z - eps * u[i].z};
        }
        bondForces(a, xp, fp);
        bondForces(a, xm, fm);
        lambda = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            const Double3 ku{-(fp[i].x - fm[i].x) / (2 * eps), -(fp[i].y - fm[i].y) / (2 * eps),
                             -(fp[i].z - fm[i].z) / (2 * eps)};
            lambda += ku.x * u[i].x + ku.y * u[i].y + ku.z * u[i].z;
            u[i] = ku;
        }
    }
    return lambda;
}

/// The cantilever (one body) `thick` particles through the thickness: the setup's factor and the
/// exact ratio sqrt(lambda_plain / lambda_corrected).
void factors(int thick, double& gershgorin, double& exact) {
    const double dp = 0.02 / thick;
    const std::string def = test::readFile(test::caseDef("cantilever2d/Cantilever2D_Def.xml"));
    const std::string tag = std::to_string(thick);
    const solver::SolidSetup c = solver::makeSolidSetup(
        solver::loadSolverCase(test::generateCase(test::scratch("stab_c" + tag), "cl", def, dp)));
    const solver::SolidSetup p = solver::makeSolidSetup(solver::loadSolverCase(test::generateCase(
        test::scratch("stab_p" + tag), "cl",
        test::replaceOnce(def, "<parameters>", "<parameters><parameter key=\"VcpmSurfaceCorrection\" value=\"0\" />"),
        dp)));
    ASSERT_EQ(c.dt_scale.size(), 1u);
    gershgorin = c.dt_scale[0];
    exact = std::sqrt(largestStiffness(p) / largestStiffness(c));
    std::printf("cantilever %d particles thick: sub-step factor %.4f (Gershgorin), %.4f (exact against the plain body)\n",
                thick, gershgorin, exact);
}

}  // namespace

// 8 particles thick the factor is the exact one within 1.5%. Broken on purpose (the factor
// forced to 1), this fails (checked: 1 against 0.8637).
TEST(SolidStability, SubStepFactorIsTheExactEigenvalueRatioAtEightParticles) {
    double g8 = 0, e8 = 0;
    factors(8, g8, e8);
    EXPECT_NEAR(g8, e8, 0.015 * e8);
    EXPECT_LT(e8, 0.95);  // the correction does stiffen the lattice
    double g2 = 0, e2 = 0, g4 = 0, e4 = 0;
    factors(4, g4, e4);
    factors(2, g2, e2);
    EXPECT_LT(e2, 1.0);
    EXPECT_LT(e4, 1.0);
}
