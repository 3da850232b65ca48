// SeaSpring — MIT licence.
/// \file test_solid_stability.cpp
/// \brief The corrected lattice's sub-step factors (solver::eigenSubStepScales: Lanczos on the
///        body with the solver's force functions against the plain bulk lattice's Bloch
///        analysis; solver::gershgorinSubStepScales, the default) against the exact ratio, the corrected body's largest eigenvalue found by
///        power iteration with the same force functions (central differences of
///        physics::solidSumAt, clampSumAt and solidBondForceAt at the rest state; clamp nodes
///        held), independently of the set-up's code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "physics/vcpm.h"
#include "physics/vcpm_substep.h"
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
    for (int it = 0; it < 400; ++it) {
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

/// The cantilever (one body) `thick` particles through the thickness: the set-up's factor, the
/// exact one against the plain bulk lattice (power iteration on the corrected body), the plain
/// body's largest eigenvalue against the bulk's, and the set-up's Lanczos estimate against the
/// power iteration.
struct Factors {
    double gershgorin = 0, eigen = 0, exact = 0, plain_over_bulk = 0, lanczos_over_power = 0, lanczos_over_long = 0;
};
Factors factors(int thick, const char* nu) {
    const double dp = 0.02 / thick;
    const std::string def = test::replaceOnce(test::readFile(test::caseDef("cantilever2d/Cantilever2D_Def.xml")),
                                              "poissratio=\"0.3975\"", std::string("poissratio=\"") + nu + "\"");
    const std::string tag = std::to_string(thick) + "_" + nu;
    const solver::SolidSetup c = solver::makeSolidSetup(
        solver::loadSolverCase(test::generateCase(test::scratch("stab_c" + tag), "cl", def, dp)));
    const solver::SolidSetup p = solver::makeSolidSetup(solver::loadSolverCase(test::generateCase(
        test::scratch("stab_p" + tag), "cl",
        test::replaceOnce(def, "<parameters>", "<parameters><parameter key=\"VcpmSurfaceCorrection\" value=\"0\" />"),
        dp)));
    Factors f;
    EXPECT_EQ(c.dt_scale.size(), 1u);
    if (c.dt_scale.size() != 1u) return f;
    const double bulk = solver::plainBulkStiffnessPerBody(c)[0];
    const double corrected = largestStiffness(c), plain = largestStiffness(p);
    f.gershgorin = c.dt_scale[0];  // the default, VcpmSubStepBound 0
    f.eigen = solver::eigenSubStepScales(c)[0];
    f.exact = std::min(1.0, std::sqrt(bulk / corrected));
    f.plain_over_bulk = plain / bulk;
    const double lanczos = solver::largestStiffnessPerBody(c, solver::kStiffnessIterations)[0];
    f.lanczos_over_power = lanczos / corrected;
    f.lanczos_over_long = lanczos / solver::largestStiffnessPerBody(c, 240)[0];
    std::printf("cantilever nu %s, %d particles thick: sub-step factor %.4f (eigenvalue), %.4f (Gershgorin), %.4f "
                "(exact against the plain bulk); "
                "plain body / bulk %.4f; Lanczos %d steps / 400 power iterations %.5f, / 240 Lanczos steps %.5f\n",
                nu, thick, f.eigen, f.gershgorin, f.exact, f.plain_over_bulk, solver::kStiffnessIterations, f.lanczos_over_power,
                f.lanczos_over_long);
    return f;
}

}  // namespace

// VcpmSubStepBound 1 (the eigenvalue factor) is at most the exact factor and within 3% of it,
// 2 to 8 particles through the thickness at nu 0.3975 and 0.49; the default (Gershgorin's) is
// within 1.5% of it 8 particles thick at nu 0.3975 and above it elsewhere (printed: up to 18%,
// 2 particles thick at nu 0.49). The plain bulk lattice's eigenvalue (the Bloch analysis) bounds
// the plain body's 8 particles thick and is reached by it within 2% (its interior holds the
// bulk's highest modes; thinner plain bodies at nu 0.49 exceed the bulk, by 0.6% at 4 and 7.5%
// at 2); 60 Lanczos steps are within 0.5% of 240 and not below 400 power iterations. Broken on
// purpose (t_half/4 for t_half/2 in D(q)), this fails (checked: the plain body at nu 0.49 then
// reads 1.78 times the "bulk"); at nu 0.3975 the bulk's largest mode has no volume change, so
// only the nu 0.49 rows see that coefficient.
TEST(SolidStability, SubStepFactorIsTheExactEigenvalueRatio) {
    for (const char* nu : {"0.3975", "0.49"})
    for (int thick : {8, 4, 2}) {
        const Factors f = factors(thick, nu);
        EXPECT_LE(f.eigen, f.exact) << nu << " " << thick;
        EXPECT_GE(f.eigen, 0.97 * f.exact) << nu << " " << thick;
        if (thick == 8 && std::string(nu) == "0.3975") {  // Gershgorin's factor (the default): near the
            EXPECT_NEAR(f.gershgorin, f.exact, 0.015 * f.exact);  // exact one only thick and away from nu 0.5
        }
        if (thick == 8) {  // thinner plain bodies at nu 0.49 exceed the bulk (1.0056 at 4, 1.0749 at 2)
            EXPECT_LE(f.plain_over_bulk, 1.0 + 1e-9) << nu;
            EXPECT_GE(f.plain_over_bulk, 0.98) << nu;
        }
        EXPECT_GE(f.lanczos_over_power, 0.995) << nu << " " << thick;
        EXPECT_GE(f.lanczos_over_long, 0.995) << nu << " " << thick;
        EXPECT_LT(f.exact, 0.95) << thick;  // the correction does stiffen the lattice
    }
}

// VcpmSubStepBound 1 puts the eigenvalue factor into the set-up (the default keeps Gershgorin's
// without the rows' bending, here switched off).
TEST(SolidStability, SubStepBoundOneUsesTheEigenvalueFactor) {
    const std::string def = test::replaceOnce(test::readFile(test::caseDef("cantilever2d/Cantilever2D_Def.xml")),
                                              "<parameters>",
                                              "<parameters><parameter key=\"VcpmRowBending\" value=\"0\" />");
    const solver::SolidSetup g = solver::makeSolidSetup(
        solver::loadSolverCase(test::generateCase(test::scratch("stab_bound0"), "cl", def, 0.005)));
    const solver::SolidSetup e = solver::makeSolidSetup(solver::loadSolverCase(test::generateCase(
        test::scratch("stab_bound1"), "cl",
        test::replaceOnce(def, "<parameters>", "<parameters><parameter key=\"VcpmSubStepBound\" value=\"1\" />"),
        0.005)));
    ASSERT_EQ(e.dt_scale.size(), 1u);
    ASSERT_EQ(g.dt_scale.size(), 1u);
    EXPECT_EQ(e.dt_scale[0], solver::eigenSubStepScales(e)[0]);
    EXPECT_EQ(g.dt_scale[0], solver::gershgorinSubStepScales(g)[0]);
    EXPECT_LT(e.dt_scale[0], g.dt_scale[0]);  // 4 particles thick: 0.8340 against 0.8554
    EXPECT_LT(e.dt, g.dt);
}

// The rows' bending (VcpmRowBending 1) in both sub-step factors, the cantilever 4 particles
// thick at nu 0.3975: the eigenvalue factor (Lanczos through the force functions, which include
// the rows) is at most the exact one from power iteration and within 3% of it, and Gershgorin's
// row sums grow with the rows' k_r c c^T terms, so its factor falls below the one without them
// (measured 0.7662 against 0.8554; eigenvalue 0.7755, exact 0.7833). Broken on purpose (the
// rows left out of Gershgorin's sums): the last check fails. The rows' set-up takes the
// eigenvalue factor by default (VcpmSubStepBound -1). The rows are on by default with the
// surface correction (VcpmRowBending -1): the case's own parameters have them.
TEST(SolidStability, RowBendingIsInBothSubStepFactors) {
    const std::string def = test::readFile(test::caseDef("cantilever2d/Cantilever2D_Def.xml"));
    const solver::SolidSetup plain = solver::makeSolidSetup(solver::loadSolverCase(test::generateCase(
        test::scratch("stab_norows"), "cl",
        test::replaceOnce(def, "<parameters>", "<parameters><parameter key=\"VcpmRowBending\" value=\"0\" />"), 0.005)));
    const solver::SolidSetup rows = solver::makeSolidSetup(
        solver::loadSolverCase(test::generateCase(test::scratch("stab_rows"), "cl", def, 0.005)));
    ASSERT_FALSE(rows.row_slot.empty());
    ASSERT_TRUE(plain.row_slot.empty());
    // VcpmSubStepBound's default (-1, auto) takes the eigenvalue factor with the rows and
    // Gershgorin's without them.
    ASSERT_EQ(rows.dt_scale.size(), 1u);
    EXPECT_EQ(rows.dt_scale[0], solver::eigenSubStepScales(rows)[0]);
    EXPECT_EQ(plain.dt_scale[0], solver::gershgorinSubStepScales(plain)[0]);
    const double bulk = solver::plainBulkStiffnessPerBody(rows)[0];
    const double exact = std::min(1.0, std::sqrt(bulk / largestStiffness(rows)));
    const double eigen = solver::eigenSubStepScales(rows)[0];
    const double g_rows = solver::gershgorinSubStepScales(rows)[0], g_plain = solver::gershgorinSubStepScales(plain)[0];
    std::printf("rows' bending, 4 particles thick, nu 0.3975: eigenvalue %.4f, exact %.4f, Gershgorin %.4f (without the "
                "rows %.4f)\n", eigen, exact, g_rows, g_plain);
    EXPECT_LE(eigen, exact);
    EXPECT_GE(eigen, 0.97 * exact);
    EXPECT_LT(g_rows, 0.95 * g_plain);
}
