// SeaSpring — MIT licence.
/// \file test_forces_ahead.cpp
/// \brief The next force evaluation launched with the divide (Backend::divideThenForces, its
///        passes gated on the divide's verdict) gives the bits of divide() then computeForces(),
///        one test body per backend (the OpenMP backend on 2 threads and the CUDA backend, which
///        skips visibly without a GPU): whole runs with SEASPRING_FORCES_AHEAD=0 and without it
///        end with the same state hash and divide counts, on cases whose divides sorted and
///        refreshed (both verdicts taken), with outputs between the steps, for Verlet with the
///        SPS stress and a moving piston, symplectic with mDBC, and a VCPM gate with gauges on
///        both schemes.
///        Broken on purpose, each failed here: settleDivide() taking every verdict for "no sort"
///        (every run test: computeForces settles through it), the gate left off the
///        evaluation's passes (Verlet with SPS, the gate), and settleDivide() dropping a valid
///        evaluation, evaluated again (the SPS cases and the contract test below: the SPS
///        stress then lags twice).
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "solver/state_hash.h"
#include "backend_kinds.h"
#include "solver_test_util.h"

using namespace seaspring;
using solver::Backend;

namespace {

using test::Cpu2;
using test::Gpu;

template <class Kind>
class ForcesAhead : public ::testing::Test {
protected:
    void SetUp() override {
        std::string why;
        if (!Kind::make(why)) GTEST_SKIP() << "no backend of this kind here: " << why;
    }
    void TearDown() override { unsetenv("SEASPRING_FORCES_AHEAD"); }
};

using Kinds = ::testing::Types<Cpu2, Gpu>;
TYPED_TEST_SUITE(ForcesAhead, Kinds);

/// One run of the case on a backend of this kind; `ahead`: launches allowed (the default) or
/// SEASPRING_FORCES_AHEAD=0.
template <class Kind>
solver::RunSummary runOn(const std::string& kase_path, const std::string& outdir, bool ahead,
                         const std::function<void(solver::RunOptions&)>& tweak) {
    if (ahead) unsetenv("SEASPRING_FORCES_AHEAD");
    else setenv("SEASPRING_FORCES_AHEAD", "0", 1);
    std::string why;
    return test::runOn(Kind::make(why), kase_path, outdir, tweak).summary;
}

/// Both ways on one case: same hash, same divides and sorts, and divides that both sorted and
/// only refreshed.
template <class Kind>
void expectSameBits(const std::string& kase, const std::string& dir, const std::string& what,
                    const std::function<void(solver::RunOptions&)>& tweak) {
    const solver::RunSummary off = runOn<Kind>(kase, dir + "/off", false, tweak);
    const solver::RunSummary on = runOn<Kind>(kase, dir + "/on", true, tweak);
    EXPECT_EQ(on.state_hash, off.state_hash) << what;
    EXPECT_EQ(on.steps, off.steps) << what;
    EXPECT_EQ(on.divides, off.divides) << what;
    EXPECT_EQ(on.sorts, off.sorts) << what;
    EXPECT_GT(on.sorts, 1ull) << what << ": no divide sorted after the first, the gated path was not taken";
    EXPECT_LT(on.sorts + 10, on.divides) << what << ": too few divides only refreshed";
    EXPECT_GE(on.outputs, 3) << what << ": the run should write out between its steps";
    std::printf("%s: %lld steps, %llu divides, %llu sorts, %d outputs, hash %s\n", what.c_str(), on.steps,
                (unsigned long long)on.divides, (unsigned long long)on.sorts, on.outputs, on.state_hash.c_str());
}


}  // namespace

TYPED_TEST(ForcesAhead, VerletSpsWithAMovingPiston) {
    const std::string dir = test::scratch("ahead_verlet_sps");
    const std::string kase = test::pistonCase(
        dir, "PistonTank2D_Def.xml",
        R"(<parameter key="StepAlgorithm" value="1" /><parameter key="VerletSteps" value="40" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="2" /><parameter key="Visco" value="1e-6" /><parameter key="DensityDT" value="1" />)");
    expectSameBits<TypeParam>(kase, dir, "Verlet, laminar+SPS, piston", [](solver::RunOptions& o) { o.nsteps = 600;
        o.tout = 0.01;
    });
}

TYPED_TEST(ForcesAhead, SymplecticMdbc) {
    const std::string dir = test::scratch("ahead_sym_mdbc");
    const std::string kase = test::pistonCase(
        dir, "PistonTankMdbc2D_Def.xml",
        R"(<parameter key="Boundary" value="2" /><parameter key="SlipMode" value="2" /><parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="3" /><parameter key="Visco" value="1e-6" /><parameter key="DensityDT" value="3" />)");
    expectSameBits<TypeParam>(kase, dir, "symplectic, mDBC slip 2, piston", [](solver::RunOptions& o) { o.nsteps = 500;
        o.tout = 0.01;
    });
}

TYPED_TEST(ForcesAhead, VerletVcpmGateWithGauges) {
    // The gate case on the Verlet scheme (one divide a step, settled by activeFluid).
    const std::string dir = test::scratch("ahead_antoci_verlet");
    const std::string def = test::replaceOnce(test::readFile(test::caseDef("antoci_gate2d/AntociGate2D_Def.xml")),
                                              R"(<parameter key="StepAlgorithm" value="2" />)",
                                              R"(<parameter key="StepAlgorithm" value="1" />)");
    const std::string kase = test::generateCase(dir, "ag", def, 0.004);
    expectSameBits<TypeParam>(kase, dir, "Antoci gate dp 4 mm, Verlet, gauges", [](solver::RunOptions& o) {
        o.tmax = 0.06;
        o.tout = 0.01;
    });
}

TYPED_TEST(ForcesAhead, VcpmGateWithGauges) {
    const std::string dir = test::scratch("ahead_antoci");
    const std::string kase = test::generateCaseFile(dir, "ag", test::caseDef("antoci_gate2d/AntociGate2D_Def.xml"), 0.004);
    expectSameBits<TypeParam>(kase, dir, "Antoci gate dp 4 mm, gauges", [](solver::RunOptions& o) {
        o.tmax = 0.06;
        o.tout = 0.01;
    });
}

// The contract of divideThenForces: until computeForces takes the evaluation launched ahead,
// what would change the state (or save it) throws, and computeForces gives the maxima of
// divide() then computeForces() on a twin backend.
TYPED_TEST(ForcesAhead, NothingChangesTheStateUntilComputeForces) {
    const std::string dir = test::scratch("ahead_contract");
    const std::string kase = test::pistonCase(
        dir, "PistonTank2D_Def.xml",
        R"(<parameter key="StepAlgorithm" value="1" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="2" /><parameter key="Visco" value="1e-6" /><parameter key="DensityDT" value="1" />)");
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const solver::BackendSetup setup = solver::makeBackendSetup(c, 0, 0.05);
    std::string why;
    std::unique_ptr<Backend> a = TypeParam::make(why), b = TypeParam::make(why);
    for (Backend* x : {a.get(), b.get()}) {
        x->init(setup);
        x->divide(false);
        x->computeForces();
        x->verletStep(1e-4, false);
    }
    a->divide(false);
    b->divideThenForces(false);
    EXPECT_TRUE(b->forcesAhead());
    EXPECT_THROW(b->verletStep(1e-4, false), std::logic_error);
    EXPECT_THROW(b->divide(false), std::logic_error);
    CheckpointData d;
    EXPECT_THROW(b->saveState(d), std::logic_error);
    EXPECT_EQ(b->activeFluid(), a->activeFluid());  // settles the verdict; the evaluation stands
    EXPECT_TRUE(b->forcesAhead());
    const physics::DtMaxima ma = a->computeForces(), mb = b->computeForces();
    EXPECT_FALSE(b->forcesAhead());
    EXPECT_EQ(ma.ace2, mb.ace2);
    EXPECT_EQ(ma.vel2, mb.vel2);
    EXPECT_EQ(ma.visc, mb.visc);
    EXPECT_NO_THROW(b->verletStep(1e-4, false));
    a->verletStep(1e-4, false);
    solver::HostState sa, sb;
    a->download(sa);
    b->download(sb);
    EXPECT_EQ(solver::hashHex(solver::stateHash(sa)), solver::hashHex(solver::stateHash(sb)));
}
