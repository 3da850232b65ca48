// SeaSpring — MIT licence.
/// \file test_fluid_accuracy.cpp
/// \brief Physical checks at coarse resolution: still water stays still with a hydrostatic
///        pressure, fluid mass is conserved, the 2D dam-break front follows Koshizuka & Oka's
///        experiment, and particles that leave the domain are excluded and counted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "physics/eos_tait.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

std::string scratch(const std::string& tag) { return test::scratch("accuracy_" + tag); }

std::string constantsDef() {
    return R"(<constantsdef><gravity x="0" y="0" z="-9.81" /><rhop0 value="1000" /><hswl value="0" auto="true" />
    <gamma value="7" /><speedsystem value="0" auto="true" /><coefsound value="20" />
    <speedsound value="0" auto="true" /><coefh value="1.0" /><cflnumber value="0.2" /></constantsdef>
  <mkconfig boundcount="240" fluidcount="9" />)";
}

const char* kSymplecticDdt3 =
    R"(<parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="1" /><parameter key="Visco" value="0.01" /><parameter key="DensityDT" value="3" />)";

}  // namespace

/// 2D tank 0.4 m wide, water 0.2 m deep, dp = 0.01, for 1 s of physical time.
/// Tolerances: |v| < 0.03 sqrt(g H) (DBC still water keeps a small residual motion near the
/// walls); mean pressure over the column centre within 5% of rho0 g (z_top - z), z_top the
/// centre of the top particle layer: weakly-compressible SPH keeps the top layer at rho0, so
/// p = 0 there, not half a dp above (measured: 2-4% below that line at 1 s, every DDT).
TEST(FluidAccuracy, StillWaterStaysStillAndHydrostatic) {
    const std::string dir = scratch("still");
    const std::string def = std::string(R"(<?xml version="1.0" encoding="UTF-8" ?>
<case><casedef>)") + constantsDef() + R"(
  <geometry><definition dp="0.01"><pointmin x="-0.05" y="0" z="-0.05" /><pointmax x="0.45" y="0" z="0.35" /></definition>
  <commands><mainlist>
    <setdrawmode mode="full" />
    <setmkfluid mk="0" /><drawbox><boxfill>solid</boxfill><point x="0" y="-1" z="0" /><size x="0.4" y="2" z="0.2" /></drawbox>
    <setmkbound mk="0" /><drawbox><boxfill>bottom | left | right</boxfill><point x="0" y="-1" z="0" /><size x="0.4" y="2" z="0.3" /><layers vdp="0,1,2" /></drawbox>
  </mainlist></commands></geometry>
</casedef>
<execution><parameters>)" + kSymplecticDdt3 + R"(
  <parameter key="TimeMax" value="1.0" /><parameter key="TimeOut" value="0.5" />
</parameters></execution></case>
)";
    const std::string kase = test::generateCase(dir, "still", def);
    const auto r = test::runCpu(kase, dir + "/out", 2);
    ASSERT_NEAR(r.summary.physical_time, 1.0, 1e-3);
    const auto& c = r.kase;
    // Mass: every fluid particle is still in the simulation (constant particle mass).
    EXPECT_EQ(r.summary.fluid_active, c.nfluid);
    EXPECT_EQ(r.summary.excluded_position + r.summary.excluded_density + r.summary.excluded_not_finite, 0u);
    const double g = 9.81, depth = 0.2, b = c.constants.b, rho0 = c.constants.rhop0;
    double vmax = 0, zmax = 0;
    for (std::size_t i = c.nfixed + c.nmoving; i < c.particles.size(); ++i) {
        const auto& v = r.state.velrho[i];
        vmax = std::max(vmax, double(std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z)));
        zmax = std::max(zmax, r.state.pos[i].z);
    }
    EXPECT_LT(vmax, 0.03 * std::sqrt(g * depth)) << "max fluid speed after 1 s";
    // Hydrostatic pressure along the centre column, binned by height.
    for (double zc : {0.03, 0.07, 0.11, 0.15}) {
        double psum = 0;
        int n = 0;
        for (std::size_t i = c.nfixed + c.nmoving; i < c.particles.size(); ++i) {
            const auto& p = r.state.pos[i];
            if (std::abs(p.x - 0.2) < 0.1 && std::abs(p.z - zc) < 0.01) {
                psum += physics::taitPressure7(r.state.velrho[i].w, float(b), float(1.0 / rho0));
                ++n;
            }
        }
        ASSERT_GT(n, 5);
        const double p_expected = rho0 * g * (zmax - zc);
        EXPECT_NEAR(psum / n, p_expected, 0.05 * p_expected) << "z = " << zc;
    }
}

namespace {
/// Time (interpolated between samples) at which the sampled front first reaches x; -1 if never.
double timeFrontReaches(const std::vector<double>& ts, const std::vector<double>& fronts, double x) {
    for (std::size_t s = 1; s < ts.size(); ++s)
        if (fronts[s] >= x)
            return ts[s - 1] + (ts[s] - ts[s - 1]) * (x - fronts[s - 1]) / std::max(1e-12, fronts[s] - fronts[s - 1]);
    return -1;
}
}  // namespace

/// DualSPHysics' CaseDambreakVal2D (column a = 1 m wide, 2 m high) at dp = 0.025, one run to
/// 0.6 s with the surge front (largest x of fluid on the floor, z < 0.1 m) sampled every 5 ms.
/// Data: ../shared/validation-data/dam-break-surge-front (T = t sqrt(2g/a), Z = x/a).
/// - Koshizuka & Oka's own MPS solution (a numerical reference of the same flow): the time at
///   which our front reaches each of its Z (T >= 0.75) within 6% of its T (measured: 1.3-3.7%
///   later than MPS).
/// - Their experiment: particle methods run ahead of it (its gate takes time to open: at
///   T < 1.4 the MPS curve leads it by up to 23%), so from T = 1.4 on, the time to reach each
///   measured Z must lie in [0.80, 1.08] x the measured T: never behind the experiment beyond
///   its +-8% digitisation band, never more than 20% ahead (measured: 7-16% ahead).
TEST(FluidAccuracy, DamBreakFrontFollowsKoshizukaOka) {
    const std::string def = std::string(SEASPRING_SHARED_DIR) + "/dualsphysics-cases/CaseDambreakVal2D_Def.xml";
    if (!std::ifstream(def)) GTEST_SKIP() << def << " is missing (real DualSPHysics cases not present)";
    const std::string dir = scratch("dambreak2d");
    const std::string kase = test::generateCaseFile(dir, "val2d", def, 0.025);
    const auto c = solver::loadSolverCase(kase);
    const std::size_t first_fluid = c.particles.size() - c.nfluid;
    std::vector<double> ts, fronts;
    const double tscale = std::sqrt(2 * 9.81 / 1.0);  // T = t sqrt(2g/a), a = 1 m
    const auto r = test::runCpu(
        kase, dir + "/out", 2,
        [&](solver::RunOptions& o) {
            o.tmax = 0.6;
            o.tout = 0.005;
            o.step_algorithm = 2;
            o.ddt = 3;
        },
        [&](double t, long long, const solver::HostState& st) {
            double front = 0;
            for (std::size_t i = first_fluid; i < st.pos.size(); ++i)
                if (st.excl[i] == 0 && st.pos[i].z < 0.1) front = std::max(front, st.pos[i].x);
            ts.push_back(t * tscale);
            fronts.push_back(front);
        });
    ASSERT_NEAR(r.summary.physical_time, 0.6, 1e-3);
    const double mps[][2] = {{0.778, 1.351}, {0.958, 1.512}, {1.095, 1.637}, {1.226, 1.771}, {1.381, 1.931},
                             {1.536, 2.100}, {1.684, 2.268}, {1.858, 2.480}, {2.043, 2.707}, {2.278, 3.004},
                             {2.451, 3.251}};
    for (const auto& m : mps) {
        const double t_sim = timeFrontReaches(ts, fronts, m[1]);
        ASSERT_GT(t_sim, 0) << "front never reached Z = " << m[1];
        EXPECT_NEAR(t_sim, m[0], 0.06 * m[0]) << "MPS point Z = " << m[1];
    }
    const double experiment[][2] = {{1.427, 1.695}, {1.630, 1.903}, {1.834, 2.123}, {1.978, 2.365},
                                    {2.196, 2.584}, {2.311, 2.804}, {2.501, 3.034}};
    for (const auto& e : experiment) {
        const double t_sim = timeFrontReaches(ts, fronts, e[1]);
        ASSERT_GT(t_sim, 0) << "front never reached Z = " << e[1];
        EXPECT_GE(t_sim, 0.80 * e[0]) << "experiment point Z = " << e[1];
        EXPECT_LE(t_sim, 1.08 * e[0]) << "experiment point Z = " << e[1];
    }
}

/// Water flowing over the edge of an open tray leaves the simulation domain: the particles are
/// excluded and counted, the run goes on to TimeMax.
TEST(FluidAccuracy, ParticlesLeavingTheDomainAreExcludedAndCounted) {
    const std::string dir = scratch("outflow");
    const std::string def = std::string(R"(<?xml version="1.0" encoding="UTF-8" ?>
<case><casedef>)") + constantsDef() + R"(
  <geometry><definition dp="0.01"><pointmin x="-0.05" y="0" z="-0.05" /><pointmax x="0.45" y="0" z="0.35" /></definition>
  <commands><mainlist>
    <setdrawmode mode="full" />
    <setmkfluid mk="0" /><drawbox><boxfill>solid</boxfill><point x="0" y="-1" z="0" /><size x="0.1" y="2" z="0.2" /></drawbox>
    <setmkbound mk="0" /><drawbox><boxfill>bottom | left</boxfill><point x="0" y="-1" z="0" /><size x="0.2" y="2" z="0.3" /></drawbox>
  </mainlist></commands></geometry>
</casedef>
<execution><parameters>)" + kSymplecticDdt3 + R"(
  <parameter key="TimeMax" value="0.5" /><parameter key="TimeOut" value="0.25" />
</parameters></execution></case>
)";
    const std::string kase = test::generateCase(dir, "tray", def);
    const auto r = test::runCpu(kase, dir + "/out", 2);
    EXPECT_NEAR(r.summary.physical_time, 0.5, 1e-3);
    EXPECT_GT(r.summary.excluded_position, 0u);
    EXPECT_EQ(r.summary.fluid_active + r.summary.excluded_position + r.summary.excluded_density +
                  r.summary.excluded_not_finite,
              r.kase.nfluid);
    // Excluded particles are outside the domain (or were when they left).
    std::uint32_t outside = 0;
    const auto& lo = r.kase.domain_min;
    const auto& hi = r.kase.domain_max;
    for (std::size_t i = 0; i < r.state.pos.size(); ++i) {
        const auto& p = r.state.pos[i];
        if (r.state.excl[i] == 1 && (p.x < lo.x || p.x > hi.x || p.z < lo.z || p.z > hi.z)) ++outside;
    }
    EXPECT_EQ(outside, r.summary.excluded_position);
}
