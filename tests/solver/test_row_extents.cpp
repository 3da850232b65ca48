// SeaSpring — MIT licence.
/// \file test_row_extents.cpp
/// \brief -rowextents (physics/neighbour_rows.h, solver's RowExtentsPass): the pair loops visit
///        the rows of cells, and the cells of a row, that the extent of the row's particles puts
///        in reach. One test body per backend (the OpenMP backend on 2 threads and the CUDA
///        backend, which skips visibly without a GPU): with one pair lane a run gives the bits of
///        the rows bounded by their cells (the same neighbours in the same order); with the pair
///        lanes auto takes for these small cases (4) the candidates each lane takes change, so
///        the hash does, and the GPU's hash equals the CPU's (its extents joined across a warp,
///        the host's formed in one pass). Cases: the 3D dam break at h = 2 dp on its
///        lattice-centred grid (where the extents cut the most), the 2D tank with laminar+SPS and
///        a moving piston, and the symplectic mDBC piston tank (the extents in a launch of their
///        own beside mDBC's).
///        Broken on purpose: a row's first cell taken from the lower x bound of its extent (cells
///        that hold neighbours left out) fails the 2D cases' one-lane check. An extent's join
///        that took an empty share's infinities as bounds (the GPU's warp over a row shorter than
///        it) made every GPU hash with pair lanes differ from the CPU's in tools/hash_table.sh;
///        the GPU instances here compare the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "backend_kinds.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

using test::Cpu2;
using test::Gpu;

template <class Kind>
class RowExtents : public ::testing::Test {
protected:
    void SetUp() override {
        std::string why;
        if (!Kind::make(why)) GTEST_SKIP() << "no backend of this kind here: " << why;
    }
};

using Kinds = ::testing::Types<Cpu2, Gpu>;
TYPED_TEST_SUITE(RowExtents, Kinds);

struct Run {
    std::string hash;
    solver::HostState state;
    double time = 0;
    std::string options;  ///< the summary's physics line
};

/// One run on a backend of kind K: `extents` on or off, `lanes` pair lanes (0: auto), n steps.
template <class K>
Run runOn(const std::string& kase_path, const std::string& outdir, bool extents, int lanes, long long n) {
    std::string why;
    const test::SolverRun s = test::runOn(K::make(why), kase_path, outdir, [&](solver::RunOptions& o) {
        o.nsteps = n;
        o.pair_lanes = lanes;
        o.row_extents = extents;
    });
    return Run{s.summary.state_hash, s.state, s.summary.physical_time, s.summary.options};
}

template <class K>
void check(const std::string& kase, const std::string& dir, const std::string& what, long long n) {
    const Run on1 = runOn<K>(kase, dir + "/on1", true, 1, n), off1 = runOn<K>(kase, dir + "/off1", false, 1, n);
    EXPECT_GT(on1.time, 0.0) << what;
    EXPECT_EQ(on1.hash, off1.hash) << what << ": one lane, extents on and off";
    EXPECT_NE(on1.options.find("rows bounded by their particles' extent"), std::string::npos) << on1.options;
    EXPECT_EQ(off1.options.find("extent"), std::string::npos) << off1.options;
    const Run on = runOn<K>(kase, dir + "/on", true, 0, n), off = runOn<K>(kase, dir + "/off", false, 0, n);
    EXPECT_NE(on.hash, off.hash) << what << ": auto lanes, the candidates of each lane change";
    double maxdiff = 0;
    for (std::size_t i = 0; i < on.state.pos.size(); ++i)
        maxdiff = std::max(maxdiff, std::abs(on.state.pos[i].z - off.state.pos[i].z));
    EXPECT_LT(maxdiff, 1e-6) << what << ": only the rounding may change";
    if (!std::is_same<K, Cpu2>::value) {
        const Run cpu = runOn<Cpu2>(kase, dir + "/cpu", true, 0, n);
        EXPECT_EQ(on.hash, cpu.hash) << what << ": this backend against the CPU, extents on, auto lanes";
    }
    std::printf("%s: %lld steps, hash with extents %s (one lane %s)\n", what.c_str(), n, on.hash.c_str(),
                on1.hash.c_str());
}

}  // namespace

TYPED_TEST(RowExtents, DamBreak3DOnALatticeCentredGrid) {
    const std::string dir = test::scratch("extents_db3d");
    std::string def = test::readFile(std::string(SEASPRING_SOURCE_DIR) + "/cases/dambreak3d/DamBreak3D_Def.xml");
    def = test::replaceOnce(def, "<coefh value=\"1.0\"", "<hdp value=\"2\"");
    check<TypeParam>(test::generateCase(dir, "db", def, 0.04), dir, "3D dam break, h = 2 dp", 25);
}

TYPED_TEST(RowExtents, PistonTank2DLaminarSps) {
    const std::string dir = test::scratch("extents_piston_sps");
    const std::string kase = test::pistonCase(
        dir, "PistonTank2D_Def.xml",
        R"(<parameter key="StepAlgorithm" value="1" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="2" /><parameter key="Visco" value="1e-6" /><parameter key="DensityDT" value="1" />)");
    check<TypeParam>(kase, dir, "2D piston tank, Verlet, laminar+SPS", 200);
}

TYPED_TEST(RowExtents, PistonTank2DSymplecticMdbc) {
    const std::string dir = test::scratch("extents_piston_mdbc");
    const std::string kase = test::pistonCase(
        dir, "PistonTankMdbc2D_Def.xml",
        R"(<parameter key="Boundary" value="2" /><parameter key="SlipMode" value="2" /><parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="3" /><parameter key="Visco" value="1e-6" /><parameter key="DensityDT" value="3" />)");
    check<TypeParam>(kase, dir, "2D piston tank, symplectic, mDBC slip 2", 200);
}
