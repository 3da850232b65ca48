// SeaSpring — MIT licence.
/// \file test_pair_lanes.cpp
/// \brief The pair lanes of the fluid loop (physics/fluid_interaction.h), on random cell-sorted
///        fluid and boundary particles in 2D and 3D, for three physics families:
///        - the host's path (every lane's partial in one batched walk, PairBatch) gives the bits
///          of the GPU's path (one direct walk per lane, fluidLanePartial), combined by
///          combineLanes, for 1, 2, 4 and 8 lanes;
///        - a warp's butterfly exchange (lane k takes lane k ^ w's value, the lower lane's first;
///          core/lane_group.h on the GPU, emulated here) leaves lane 0 with combineLanes' result;
///        - the GPU's masked rows (fluidPairsInRowMasked) give the direct walk's bits, lane by
///          lane, also on rows longer than one 32-bit mask;
///        - the boundary particles' batched filter (boundParticleForces' host path: eight
///          candidates at a time where the host has AVX2) gives the direct walk's bits;
///        - one lane is the plain sum, and more lanes change only the rounding: every candidate
///          lands in exactly one lane (the sums agree to float rounding, and a lane left out or
///          counted twice is far outside it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "physics/cell_grid.h"
#include "physics/fluid_constants.h"
#include "physics/fluid_interaction.h"
#include "pair_blocks.h"

using namespace seaspring::physics;

namespace {

/// Random fluid particles over a box and boundary particles in a floor layer, each block sorted by
/// cell (then index), with random velocities, densities (hence pressures) and SPS stresses.
struct Scene : seaspring::test::PairBlocks {};

Scene makeScene(int dim, int cell_div, std::mt19937& rng, std::uint32_t density = 1) {
    Scene s;
    const double dp = 0.01, h = 1.5 * dp;
    const double lx = 0.3, ly = dim == 3 ? 0.12 : 0.0, lz = 0.2;
    EXPECT_TRUE(makeCellGrid(-0.03, dim == 3 ? -0.03 : 0.0, -0.03, lx + 0.03, dim == 3 ? ly + 0.03 : 0.0, lz + 0.03, h,
                             cell_div, s.g, 0.05));
    s.c = seaspring::test::pairTestFluid(dim, dp, h);  // artificial alpha, or laminar nu (scaled below)
    s.nf = (dim == 3 ? 2500 : 700) * density;
    s.nb = (dim == 3 ? 900 : 120) * density;
    std::uniform_real_distribution<double> ux(0, lx), uy(0, ly), uz(0, lz), ub(-0.02, 0.0), uv(-0.5, 0.5),
        urho(990, 1015), ut(-1e-4, 1e-4);
    auto block = [&](std::uint32_t n, bool bound, std::uint32_t first, std::vector<std::uint32_t>& cs) {
        std::vector<Float4> pc(n), vr(n);
        std::vector<std::uint32_t> cell(n);
        for (std::uint32_t k = 0; k < n; ++k) {
            const Double3 p{ux(rng), dim == 3 ? uy(rng) : 0.0, bound ? ub(rng) : uz(rng)};
            pc[k] = makePosCell(s.g, p, cell[k]);
            vr[k] = Float4{float(uv(rng)), dim == 3 ? float(uv(rng)) : 0.f, float(uv(rng)), float(urho(rng))};
        }
        seaspring::test::placeSortedBlock(s.g, pc, cell, vr, first, s.poscell, s.velrho, cs);
    };
    const std::uint32_t np = s.nb + s.nf;
    s.poscell.resize(np);
    s.velrho.resize(np);
    block(s.nb, true, 0, s.cs_bound);
    block(s.nf, false, s.nb, s.cs_fluid);
    s.press_ovrho.resize(np);
    s.tau.resize(np);
    for (std::uint32_t i = 0; i < np; ++i) {
        const float rho = s.velrho[i].w;
        s.press_ovrho[i] = Float2{taitPressure7(rho, s.c.cteb, s.c.ovrhop0), 1.f / rho};
        s.tau[i] = SymTensor{float(ut(rng)), float(ut(rng)), float(ut(rng)), float(ut(rng)), float(ut(rng)), float(ut(rng))};
    }
    return s;
}

bool sameBits(float a, float b) { return floatBitsToUint(a) == floatBitsToUint(b); }

template <class Opt>
::testing::AssertionResult sameAccum(const FluidAccum& a, const FluidAccum& b) {
    const float fa[] = {a.ax, a.ay, a.az, a.ar, a.delta, a.visc};
    const float fb[] = {b.ax, b.ay, b.az, b.ar, b.delta, b.visc};
    for (int k = 0; k < 6; ++k)
        if (!sameBits(fa[k], fb[k])) return ::testing::AssertionFailure() << "field " << k << ": " << fa[k] << " vs " << fb[k];
    if (a.ddt_off != b.ddt_off) return ::testing::AssertionFailure() << "ddt_off";
    if (Opt::sps) {
        const float ga[] = {a.gradvel.xx, a.gradvel.xy, a.gradvel.xz, a.gradvel.yy, a.gradvel.yz, a.gradvel.zz};
        const float gb[] = {b.gradvel.xx, b.gradvel.xy, b.gradvel.xz, b.gradvel.yy, b.gradvel.yz, b.gradvel.zz};
        for (int k = 0; k < 6; ++k)
            if (!sameBits(ga[k], gb[k])) return ::testing::AssertionFailure() << "gradvel " << k;
    }
    return ::testing::AssertionSuccess();
}

/// Lane 0's value after a warp's butterfly over `lanes` values (combine(lower lane's, upper's)).
template <class Opt>
FluidAccum butterflyLaneZero(std::vector<FluidAccum> v) {
    const std::uint32_t lanes = std::uint32_t(v.size());
    for (std::uint32_t w = 1; w < lanes; w <<= 1) {
        std::vector<FluidAccum> next(lanes);
        for (std::uint32_t k = 0; k < lanes; ++k) {
            const std::uint32_t o = k ^ w;
            next[k] = (k & w) ? combineLanePair<Opt>(v[o], v[k]) : combineLanePair<Opt>(v[k], v[o]);
        }
        v = next;
    }
    return v[0];
}

/// The most candidates of one row that a fluid particle of the scene visits (either block).
template <int kDim>
std::uint32_t longestRow(const Scene& s) {
    std::uint32_t most = 0;
    for (std::uint32_t i = s.nb; i < s.nb + s.nf; ++i)
        for (const std::uint32_t* cs : {s.cs_fluid.data(), s.cs_bound.data()})
            forEachCandidateRow<kDim>(s.poscell[i], cs, s.c, s.g,
                                      [&](std::uint32_t pb, std::uint32_t pe, const Float4&, int) {
                                          most = std::max(most, pe - pb);
                                      });
    return most;
}

template <class Opt>
void checkLanes(int cell_div, std::uint32_t seed, std::uint32_t density = 1) {
    std::mt19937 rng(seed);
    Scene s = makeScene(Opt::dim, cell_div, rng, density);
    if (Opt::visco != Viscosity::Artificial) {
        s.c.visco = 1e-3f;  // a laminar nu that matters against the pressure terms
        s.c.visco_bound = 7e-4f;
    }
    const InteractionInputs in = s.inputs();
    double worst = 0;       // largest lane-count difference, relative to the sum of |terms| scale
    double scale_sum = 0;
    long long wall_pairs = 0;
    for (std::uint32_t i = s.nb; i < s.nb + s.nf; ++i) {
        const FluidAccum one = fluidParticleForces<Opt, true>(i, in, s.c, s.g, 1);
        ASSERT_TRUE(sameAccum<Opt>(one, fluidParticleForces<Opt, false>(i, in, s.c, s.g, 1))) << "particle " << i;
        // The GPU's masked rows (fluidPairsInRowMasked, the laminar families' path): the direct
        // walk's bits, lane by lane.
        for (std::uint32_t lanes : {1u, 2u, 4u, 8u})
            for (std::uint32_t l = 0; l < lanes; ++l)
                ASSERT_TRUE(sameAccum<Opt>(fluidLanePartial<Opt, true>(i, l, lanes, in, s.c, s.g),
                                           fluidLanePartial<Opt, false>(i, l, lanes, in, s.c, s.g)))
                    << "masked rows against the direct walk, lane " << l << " of " << lanes << ", particle " << i;
        wall_pairs += one.ddt_off ? 1 : 0;
        const double mag = std::abs(one.ax) + std::abs(one.ay) + std::abs(one.az);
        scale_sum += mag;
        for (std::uint32_t lanes : {2u, 4u, 8u}) {
            const FluidAccum host = fluidParticleForces<Opt, true>(i, in, s.c, s.g, lanes);
            ASSERT_TRUE(sameAccum<Opt>(host, fluidParticleForces<Opt, false>(i, in, s.c, s.g, lanes)))
                << "host's batched lanes against one walk per lane, " << lanes << " lanes, particle " << i;
            std::vector<FluidAccum> part(lanes);
            for (std::uint32_t l = 0; l < lanes; ++l) part[l] = fluidLanePartial<Opt>(i, l, lanes, in, s.c, s.g);
            FluidAccum warp = butterflyLaneZero<Opt>(part);
            finishFluidAccum<Opt>(warp);
            ASSERT_TRUE(sameAccum<Opt>(host, warp)) << "the warp's butterfly, " << lanes << " lanes, particle " << i;
            EXPECT_EQ(host.ddt_off, one.ddt_off);
            EXPECT_EQ(host.visc, one.visc);  // a maximum: exact in any order
            const double d = std::abs(host.ax - one.ax) + std::abs(host.ay - one.ay) + std::abs(host.az - one.az);
            worst = std::max(worst, d / (mag + 1e-3));
        }
    }
    // Float rounding of sums of a few hundred terms: far below 1e-4 of the acceleration's size; a
    // lane missing (1/lanes of the neighbours) would be of order 1e-1.
    EXPECT_LT(worst, 1e-4) << Opt::dim << "D, cells of 2h/" << cell_div;
    EXPECT_GT(scale_sum, 0.0);
    if (Opt::ddt == DensityDiffusion::Fourtakas) {
        EXPECT_GT(wall_pairs, 0);  // boundary neighbours occur
    }
}

}  // namespace

TEST(PairLanes, ArtificialDdt3In2DAnd3D) {
    checkLanes<FluidOptions<WendlandKernel, Viscosity::Artificial, DensityDiffusion::FourtakasFull, 2>>(2, 11);
    checkLanes<FluidOptions<WendlandKernel, Viscosity::Artificial, DensityDiffusion::FourtakasFull, 3>>(4, 12);
}

TEST(PairLanes, CubicLaminarMolteniAndWendlandSps) {
    checkLanes<FluidOptions<CubicKernel, Viscosity::Laminar, DensityDiffusion::Molteni, 2>>(1, 13);
    checkLanes<FluidOptions<WendlandKernel, Viscosity::LaminarSps, DensityDiffusion::Fourtakas, 3>>(2, 14);
}

TEST(PairLanes, MaskedRowsKeepTheDirectWalksBitsOnRowsLongerThanAMask) {
    // Cells of 2h and four times the particles: rows of more than 32 candidates, which the masked
    // walk takes 32 at a time.
    using Opt = FluidOptions<WendlandKernel, Viscosity::LaminarSps, DensityDiffusion::Fourtakas, 2>;
    std::mt19937 rng(15);
    EXPECT_GT(longestRow<2>(makeScene(2, 1, rng, 4)), 64u);
    checkLanes<Opt>(1, 15, 4);
}

/// Each boundary particle's continuity sum and viscous dt measure through the host's batched
/// filter against the direct walk (the GPU's loop), bit for bit.
template <class Opt>
void checkBoundaryParticles(int cell_div, std::uint32_t seed) {
    std::mt19937 rng(seed);
    const Scene s = makeScene(Opt::dim, cell_div, rng);
    const InteractionInputs in = s.inputs();
    int wet = 0;
    for (std::uint32_t i = 0; i < s.nb; ++i) {
        float ar1 = -1.f, visc1 = -1.f, ar2 = -2.f, visc2 = -2.f;
        boundParticleForces<Opt, true>(i, in, s.c, s.g, ar1, visc1);
        boundParticleForces<Opt, false>(i, in, s.c, s.g, ar2, visc2);
        ASSERT_TRUE(sameBits(ar1, ar2) && sameBits(visc1, visc2))
            << Opt::dim << "D boundary particle " << i << ": " << ar1 << " vs " << ar2 << ", " << visc1 << " vs " << visc2;
        wet += ar1 != 0.f ? 1 : 0;
    }
    EXPECT_GT(wet, int(s.nb) / 4) << "boundary particles with fluid neighbours";
}

TEST(PairLanes, BoundaryParticlesBatchedGiveTheDirectWalksBits) {
    checkBoundaryParticles<FluidOptions<WendlandKernel, Viscosity::Artificial, DensityDiffusion::None, 2>>(2, 16);
    checkBoundaryParticles<FluidOptions<WendlandKernel, Viscosity::Artificial, DensityDiffusion::None, 3>>(4, 17);
    checkBoundaryParticles<FluidOptions<CubicKernel, Viscosity::Artificial, DensityDiffusion::None, 3>>(2, 18);
}

TEST(PairLanes, CombineLanesIsThePairwiseTree) {
    using Opt = FluidOptions<WendlandKernel, Viscosity::LaminarSps, DensityDiffusion::Fourtakas, 3>;
    // Values whose sums round differently in other orders: 1e8 + 1 - 1e8 ...
    FluidAccum a[4];
    const float x[4] = {1e8f, 1.f, -1e8f, 1.f};
    for (int k = 0; k < 4; ++k) {
        a[k].ax = x[k];
        a[k].gradvel = SymTensor{x[k], 0, 0, 0, 0, 0};
        a[k].visc = float(k);
        a[k].ddt_off = k == 3;
    }
    combineLanes<Opt>(a, 4);
    EXPECT_EQ(a[0].ax, (1e8f + 1.f) + (-1e8f + 1.f));  // = 0 in float; ((1e8 + 1) - 1e8) + 1 = 1
    EXPECT_EQ(a[0].gradvel.xx, a[0].ax);
    EXPECT_EQ(a[0].visc, 3.f);
    EXPECT_TRUE(a[0].ddt_off);
}
