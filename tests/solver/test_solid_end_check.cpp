// SeaSpring — MIT licence.
/// \file test_solid_end_check.cpp
/// \brief The per-step blow-up test of the solids at the end of a step's own sub-cycle: its
///        checks run in the sub-cycle's last pass (solver::SolidEndPass) and the reduction
///        behind it only counts the alarms (SolidAlarmPass). A bond that passes the strain bound
///        only at the end positions of the last sub-step (not at its start, not at its midpoint)
///        must raise the alarm that Backend::solidsPastBounds() reports right after the cycle.
///        One test body per backend (OpenMP, CUDA, CUDA with bond lanes; the CUDA instances skip
///        visibly without a GPU). Broken on purpose (the last pass's checks left out): it fails.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "physics/blowup_bounds.h"
#include "solver/motion_player.h"
#include "backend_kinds.h"
#include "solver_test_util.h"

using namespace seaspring;
using solver::Backend;

namespace {

using test::Cpu2;
using test::Gpu;
using GpuBondLanes2 = test::GpuBondLanes<2, true>;  // the sub-cycle as one launch per pass, two threads per particle

template <class Kind>
class SolidEndCheck : public ::testing::Test {};
using Kinds = ::testing::Types<Cpu2, Gpu, GpuBondLanes2>;
TYPED_TEST_SUITE(SolidEndCheck, Kinds);

/// The cantilever 2D (solid only) with its free end's particle launched along +x to move
/// `stretch_per_substep` dp in a sub-step (the speed bound off), one sub-cycle of one sub-step
/// as a step's own (ledger) cycle; returns what solidsPastBounds() reports after it (-1: no
/// backend of this kind) and, in `alarm_time`, the time of the first alarm raised (-1: none).
template <class Kind>
long long alarmsAfterOneSubStep(double stretch_per_substep, std::string& why, double& alarm_time, double& dt) {
    std::unique_ptr<Backend> b = Kind::make(why);
    if (!b) return -1;
    const std::string dir = test::scratch("solid_end_check");
    const std::string kase_path = test::generateCaseFile(dir, "cl", test::caseDef("cantilever2d/Cantilever2D_Def.xml"), 0.005);
    const solver::SolverCase kase = solver::loadSolverCase(kase_path);
    solver::BackendSetup setup = solver::makeBackendSetup(kase, 0, physics::kDefaultSkinFraction);
    solver::SolidSetup& s = setup.solid;
    std::size_t tip = 0;
    for (std::size_t i = 1; i < s.pos.size(); ++i)
        if (s.pos[i].x > s.pos[tip].x || (s.pos[i].x == s.pos[tip].x && s.pos[i].z > s.pos[tip].z)) tip = i;
    s.vel[tip].x = stretch_per_substep * kase.constants.dp / s.dt;
    for (physics::VcpmMaterial& m : s.materials) m.max_speed = 1e300;
    b->init(setup);
    b->divide(false);
    b->solidSteps(0.0, s.dt, 1, solver::motionPosesOver(kase.motion, 0.0, s.dt), true);
    const long long n = (long long)b->solidsPastBounds();
    solver::HostState st;
    b->download(st);
    alarm_time = -1;
    for (const physics::SolidAlarm& a : st.solid_alarm)
        if (a.kind != physics::kSolidAlarmNone && (alarm_time < 0 || a.time < alarm_time)) alarm_time = a.time;
    dt = s.dt;
    return n;
}

}  // namespace

// The tip moves 1.8 dp in one sub-step: its bonds pass kMaxBondStrain (1) at the end positions
// only (0.9 dp at the midpoint, where the sums pass checks them, less the bonds' pull); at rest
// nothing is raised (the test can fail either way).
TYPED_TEST(SolidEndCheck, AStrainPastTheBoundAtTheEndOfTheCycleIsCounted) {
    std::string why;
    double t = 0, dt = 0;
    const long long moving = alarmsAfterOneSubStep<TypeParam>(1.8, why, t, dt);
    if (moving < 0) GTEST_SKIP() << why;
    EXPECT_GE(moving, 1) << "the end positions' bond check did not run";
    EXPECT_EQ(t, dt) << "raised at t = " << t << ", not by the check at the cycle's end (dt = " << dt << ")";
    EXPECT_EQ(alarmsAfterOneSubStep<TypeParam>(0.0, why, t, dt), 0);
    EXPECT_EQ(t, -1.0);
}
