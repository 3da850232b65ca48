// SeaSpring — MIT licence.
/// \file test_backend_outflow.cpp
/// \brief Particles that leave the domain between two sorts (one test body per backend: OpenMP on
///        2 threads and CUDA, each against the 1-thread OpenMP backend). A divide that does not
///        sort removes an excluded particle from the run in its slot (physics::removedPosCell)
///        rather than sorting for it; the next sort drops it to the block's tail. Checked: the
///        bits of every backend alike; removals that came without a sort; the active count; and
///        the run the same, up to the summation order, as one sorted at every divide (where
///        every excluded particle leaves the active range at once); a restart in between.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "backend_kinds.h"
#include "solver_test_util.h"

using namespace seaspring;
using solver::Backend;

namespace {

/// A 2D water block (11 x 21 particles, dp 1 cm) beside a wall, falling freely out of the
/// domain's floor (the particles' bounding box there: the wall's bottom), in no particular
/// order: the wall holds back the particles beside it.
const char* kOutflowCase = R"(<?xml version="1.0" encoding="UTF-8" ?>
<case><casedef>
  <constantsdef><gravity x="0" y="0" z="-9.81" /><rhop0 value="1000" /><hswl value="0" auto="true" />
    <gamma value="7" /><speedsystem value="0" auto="true" /><coefsound value="20" />
    <speedsound value="0" auto="true" /><coefh value="1.0" /><cflnumber value="0.2" /></constantsdef>
  <mkconfig boundcount="240" fluidcount="9" />
  <geometry><definition dp="0.01"><pointmin x="-0.05" y="0" z="0.15" /><pointmax x="0.3" y="0" z="0.6" /></definition>
  <commands><mainlist>
    <setdrawmode mode="full" />
    <setmkfluid mk="0" /><drawbox><boxfill>solid</boxfill><point x="0.01" y="-1" z="0.21" /><size x="0.1" y="2" z="0.2" /></drawbox>
    <setmkbound mk="0" /><drawbox><boxfill>solid</boxfill><point x="0" y="-1" z="0.2" /><size x="0" y="2" z="0.3" /></drawbox>
  </mainlist></commands></geometry>
</casedef>
<execution><parameters>
  <parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="1" />
  <parameter key="Visco" value="0.05" /><parameter key="DensityDT" value="1" />
  <parameter key="TimeMax" value="1" /><parameter key="TimeOut" value="0.1" />
  <simulationdomain><posmin x="default" y="default" z="default" /><posmax x="default + 0.2" y="default" z="default" /></simulationdomain>
</parameters></execution></case>
)";

template <class Kind>
class BackendOutflow : public ::testing::Test {
protected:
    void SetUp() override {
        std::string why;
        if (!Kind::make(why)) GTEST_SKIP() << "no backend of this kind here: " << why;
    }
};

using Kinds = ::testing::Types<test::Cpu2, test::Gpu>;
TYPED_TEST_SUITE(BackendOutflow, Kinds);

/// One symplectic step as the solver runs it (forces, predictor, divide keeping the step
/// start, forces, corrector, divide); the first evaluation's dt maxima.
physics::DtMaxima symplecticStep(Backend& b, double dt) {
    const physics::DtMaxima m = b.computeForces();
    b.symplecticPredictor(dt);
    b.divide(true);
    b.computeForces();
    b.symplecticCorrector(dt);
    b.divide(false);
    return m;
}

/// |a - b| / |b| (the dt maxima of two runs that differ by their summation order).
double relDiff(float a, float b) { return std::fabs(double(a) - double(b)) / std::fabs(double(b)); }

std::uint32_t activeInState(const solver::HostState& s, std::uint32_t nbound) {
    std::uint32_t n = 0;
    for (std::size_t i = nbound; i < s.excl.size(); ++i) n += s.excl[i] == physics::kActive ? 1u : 0u;
    return n;
}

TYPED_TEST(BackendOutflow, ExcludedParticlesLeaveTheRunInTheirSlotsAsIfSortedOut) {
    const std::string dir = test::scratch("backend_outflow");
    const std::string kase_path = test::generateCase(dir, "outflow", kOutflowCase);
    const solver::SolverCase kase = solver::loadSolverCase(kase_path);
    // A wide skin: the falling block sorts rarely, particles leave the domain at other divides.
    const solver::BackendSetup lazy = solver::makeBackendSetup(kase, 0, 0.3);
    const solver::BackendSetup every = solver::makeBackendSetup(kase, 0, 0.0);  // a sort at every divide
    std::string why;
    std::unique_ptr<Backend> b = TypeParam::make(why), ref = solver::makeCpuBackend(1),
                             sorted = solver::makeCpuBackend(1);
    ASSERT_TRUE(b) << why;
    b->init(lazy);
    ref->init(lazy);
    sorted->init(every);
    const double dt = 2e-4;
    for (Backend* x : {b.get(), ref.get(), sorted.get()}) x->divide(false);
    const std::uint32_t nfluid = ref->activeFluid();
    ASSERT_EQ(nfluid, 231u);
    int removed_without_sort = 0;
    double worst_maxima = 0;
    std::unique_ptr<Backend> restarted;  // from a restart state holding removed particles
    for (int s = 0; s < 600; ++s) {  // 0.12 s: the block falls 7 cm
        if (restarted) symplecticStep(*restarted, dt);
        const std::uint32_t sorts0 = ref->divideCounts().sorts, active0 = ref->activeFluid();
        const physics::DtMaxima m = symplecticStep(*ref, dt);
        symplecticStep(*b, dt);
        const physics::DtMaxima ms = symplecticStep(*sorted, dt);
        // The dt maxima over the particles in the run, within 2e-2 (2026-11-28: at most 1.7e-3;
        // broken on purpose, a removed particle's dt measure not skipped: 5.9e-2).
        const double d = std::max({relDiff(m.ace2, ms.ace2), relDiff(m.vel2, ms.vel2), relDiff(m.visc, ms.visc)});
        worst_maxima = std::max(worst_maxima, d);
        ASSERT_LT(d, 2e-2) << "step " << s << ": dt maxima " << m.ace2 << ", " << m.vel2 << ", " << m.visc << " against "
            << ms.ace2 << ", " << ms.vel2 << ", " << ms.visc << " sorted at every divide";
        const std::uint32_t active1 = ref->activeFluid();
        if (active1 < active0 && ref->divideCounts().sorts == sorts0) {
            ++removed_without_sort;
            if (!restarted && s >= 200) {  // a restart state with particles removed in their slots
                CheckpointData ck;
                ref->saveState(ck);
                restarted = solver::makeCpuBackend(1);
                restarted->init(lazy);
                restarted->loadState(ck);
                // They count as removed after the load (broken on purpose, the count not formed
                // at the load: more active than the run it continues).
                ASSERT_EQ(restarted->activeFluid(), active1) << "after the restart at step " << s;
            }
        }
        ASSERT_EQ(b->activeFluid(), active1) << "step " << s;
        ASSERT_EQ(sorted->activeFluid(), active1) << "step " << s << ": the run sorted at every divide";
    }
    solver::HostState x, y, z, w;
    ref->download(x);
    b->download(y);
    sorted->download(z);
    ASSERT_TRUE(restarted) << "no divide after step 200 removed particles without a sort";
    restarted->download(w);
    EXPECT_EQ(restarted->activeFluid(), ref->activeFluid());
    EXPECT_EQ(0, std::memcmp(x.pos.data(), w.pos.data(), x.pos.size() * sizeof(x.pos[0])))
        << "the run continued from the restart state";
    // Every backend alike, bit for bit.
    EXPECT_EQ(0, std::memcmp(x.pos.data(), y.pos.data(), x.pos.size() * sizeof(x.pos[0])));
    EXPECT_EQ(0, std::memcmp(x.velrho.data(), y.velrho.data(), x.velrho.size() * sizeof(x.velrho[0])));
    EXPECT_EQ(x.excl, y.excl);
    // Rows of particles left (2026-11-28: 71 particles), some of them at divides that did
    // not sort (broken on purpose, an excluded particle asking for a sort as before: none).
    const std::uint32_t active = activeInState(x, lazy.nbound);
    EXPECT_EQ(ref->activeFluid(), active);
    EXPECT_GE(nfluid - active, 33u) << "at least three rows of 11 left the domain";
    EXPECT_GT(removed_without_sort, 0) << "divides that removed particles without a sort";
    // The same run as one sorted at every divide, up to the summation order: the same particles
    // excluded for the same reason, every position within 1e-6 m (a removed particle that moved
    // on, or one that still acted on its neighbours, differs by millimetres; broken on purpose,
    // the integration not skipping removed particles: 5.2e-3 m).
    EXPECT_EQ(x.excl, z.excl);
    double worst = 0;
    for (std::size_t i = 0; i < x.pos.size(); ++i)
        worst = std::max({worst, std::fabs(x.pos[i].x - z.pos[i].x), std::fabs(x.pos[i].z - z.pos[i].z)});
    EXPECT_LT(worst, 1e-6) << "the largest position difference from the run sorted at every divide [m]";
    std::printf("outflow: %u of %u fluid particles left, %d removals without a sort, %llu sorts of %llu divides; "
                "largest position difference from sorting at every divide %.3g m, dt maxima %.3g\n",
                nfluid - active, nfluid, removed_without_sort, (unsigned long long)ref->divideCounts().sorts,
                (unsigned long long)ref->divideCounts().divides, worst, worst_maxima);
}

}  // namespace
