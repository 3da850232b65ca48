// SeaSpring — MIT licence.
/// \file test_fluid_pair_queue.cpp
/// \brief The lane-queued force evaluation (physics/fluid_pair_queue.h, the GPU's fluid pair
///        loop) gives the same bits as the direct loop (fluidParticleForces), on a disordered
///        3D and 2D water block beside a wall, for every viscosity and density diffusion. Here
///        it runs in a one-lane group with rings of several sizes, and in groups of host threads
///        kept in lockstep at every vote (a warp emulated); the GPU's warps are compared byte for
///        byte with the CPU in test_backend_phases.
///        Broken on purpose, each failed all three tests: evaluating a lane's slots from the last
///        one (the order of the sums changes), and evaluating only full batches (a lane's last,
///        partial batch is lost).
#include <gtest/gtest.h>

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include "physics/fluid_interaction.h"
#include "physics/fluid_pair_queue.h"
#include "physics/sph_kernels.h"

using namespace seaspring::physics;

namespace {

/// A jittered lattice of fluid above three layers of wall, cell-sorted per block (boundary
/// block first, as the solver stores them), with pressures and velocities that vary.
struct Scene {
    CellGrid g;
    FluidConstants c;
    std::vector<Float4> poscell, velrho;
    std::vector<Float2> press_ovrho;
    std::vector<SymTensor> tau;
    std::vector<std::uint32_t> cs_bound, cs_fluid;
    std::uint32_t nbound = 0, n = 0;
    InteractionInputs in;
};

template <int kDim>
Scene makeScene(std::uint32_t seed) {
    Scene s;
    const double dp = 0.01, h = 2.0 * dp;
    FluidInputs fi;
    fi.h = h;
    fi.dp = dp;
    fi.dim = kDim;
    fi.cs0 = 20.0;
    fi.rhop0 = 1000.0;
    fi.b = 20.0 * 20.0 * 1000.0 / 7.0;
    fi.massfluid = fi.massbound = 1000.0 * (kDim == 3 ? dp * dp * dp : dp * dp);
    fi.visco = 0.01;
    fi.ddt_value = 0.1;
    fi.gravity_z = -9.81;
    s.c = makeFluidConstants(fi);
    const double lx = 0.16, ly = kDim == 3 ? 0.12 : 0.0, lz = 0.14;
    EXPECT_TRUE(makeCellGrid(0, 0, 0, lx, ly, lz, h, 2, s.g, 0.05));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jit(-0.2 * dp, 0.2 * dp), uv(-0.5, 0.5), ur(990.0, 1010.0);
    struct P { Double3 x; bool bound; std::uint32_t cell; };
    std::vector<P> ps;
    const int nx = int(lx / dp), ny = kDim == 3 ? int(ly / dp) : 1, nz = int(lz / dp);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const bool bound = k < 3;
                const Double3 x{(i + 0.5) * dp + (bound ? 0.0 : jit(rng)), kDim == 3 ? (j + 0.5) * dp + jit(rng) : 0.0,
                                (k + 0.5) * dp + (bound ? 0.0 : jit(rng))};
                ps.push_back(P{x, bound, 0});
            }
    std::vector<Float4> pc(ps.size());
    for (std::size_t k = 0; k < ps.size(); ++k) pc[k] = makePosCell(s.g, ps[k].x, ps[k].cell);
    std::vector<std::uint32_t> order(ps.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        if (ps[a].bound != ps[b].bound) return ps[a].bound;
        return ps[a].cell < ps[b].cell;
    });
    const std::uint32_t nc = s.g.cellCount();
    s.cs_bound.assign(nc + 1, 0);
    s.cs_fluid.assign(nc + 1, 0);
    for (std::uint32_t o : order) {
        s.poscell.push_back(pc[o]);
        const float rho = float(ur(rng));
        s.velrho.push_back(Float4{float(uv(rng)), kDim == 3 ? float(uv(rng)) : 0.f, float(uv(rng)), rho});
        s.press_ovrho.push_back(Float2{taitPressure7(rho, s.c.cteb, s.c.ovrhop0), 1.f / rho});
        s.tau.push_back(SymTensor{float(uv(rng)), float(uv(rng)), float(uv(rng)), float(uv(rng)), float(uv(rng)),
                                  float(uv(rng))});
        (ps[o].bound ? s.cs_bound : s.cs_fluid)[ps[o].cell + 1] += 1;
        s.nbound += ps[o].bound ? 1u : 0u;
    }
    s.n = std::uint32_t(order.size());
    // Cell starts: absolute indices (boundary block [0, nbound), fluid block [nbound, n)).
    s.cs_fluid[0] = s.nbound;
    for (std::uint32_t k = 0; k < nc; ++k) {
        s.cs_bound[k + 1] += s.cs_bound[k];
        s.cs_fluid[k + 1] += s.cs_fluid[k];
    }
    s.in.poscell = s.poscell.data();
    s.in.velrho = s.velrho.data();
    s.in.press_ovrho = s.press_ovrho.data();
    s.in.tau = s.tau.data();
    s.in.cell_start_bound = s.cs_bound.data();
    s.in.cell_start_fluid = s.cs_fluid.data();
    return s;
}

template <class Opt, class Lanes>
void expectSameBits(const Scene& s, const char* what) {
    int boundary_pairs = 0;
    for (std::uint32_t i = s.nbound; i < s.n; ++i) {
        const FluidAccum direct = fluidParticleForces<Opt, false>(i, s.in, s.c, s.g);
        Lanes lanes;
        const FluidAccum queued = fluidParticleForcesQueued<Opt>(i, true, s.in, s.c, s.g, lanes);
        ASSERT_EQ(std::memcmp(&direct.ax, &queued.ax, 6 * sizeof(float)), 0)
            << what << ", particle " << i << ": " << direct.ax << " " << queued.ax << ", " << direct.ar << " " << queued.ar;
        ASSERT_EQ(direct.ddt_off, queued.ddt_off) << what << ", particle " << i;
        ASSERT_EQ(std::memcmp(&direct.gradvel, &queued.gradvel, sizeof direct.gradvel), 0) << what << ", particle " << i;
        boundary_pairs += direct.ddt_off ? 1 : 0;
    }
    // A lane without a particle takes part and yields zeros.
    Lanes lanes;
    const FluidAccum none = fluidParticleForcesQueued<Opt>(0u, false, s.in, s.c, s.g, lanes);
    EXPECT_EQ(none.ax, 0.f);
    EXPECT_EQ(none.ar, 0.f);
    (void)boundary_pairs;
}

template <int kDim>
void checkAllOptions(std::uint32_t seed) {
    const Scene s = makeScene<kDim>(seed);
    using W = WendlandKernel;
    using C = CubicKernel;
    using Lanes = SingleLane<16>;
    expectSameBits<FluidOptions<W, Viscosity::Artificial, DensityDiffusion::FourtakasFull, kDim>, Lanes>(s, "artificial, DDT 3");
    expectSameBits<FluidOptions<W, Viscosity::Artificial, DensityDiffusion::Fourtakas, kDim>, Lanes>(s, "artificial, DDT 2");
    expectSameBits<FluidOptions<C, Viscosity::Laminar, DensityDiffusion::Molteni, kDim>, Lanes>(s, "cubic laminar, DDT 1");
    expectSameBits<FluidOptions<W, Viscosity::LaminarSps, DensityDiffusion::None, kDim>, Lanes>(s, "SPS");
    // Other batch sizes: one pair, and an odd size.
    expectSameBits<FluidOptions<W, Viscosity::Artificial, DensityDiffusion::FourtakasFull, kDim>, SingleLane<1>>(s, "batch 1");
    expectSameBits<FluidOptions<W, Viscosity::LaminarSps, DensityDiffusion::None, kDim>, SingleLane<7>>(s, "batch 7");
}

/// A group of host threads in lockstep at every vote (a warp's any, emulated with a barrier),
/// each with its own slots: exercises what a one-lane group never does (lanes that have run out
/// of candidates taking part in the rounds of the others).
struct Barrier {
    std::mutex m;
    std::condition_variable cv;
    int lanes = 0, arrived = 0, yes = 0;
    unsigned long long generation = 0;
    bool result = false;
    bool any(bool p) {
        std::unique_lock<std::mutex> lock(m);
        yes += p ? 1 : 0;
        if (++arrived == lanes) {
            result = yes > 0;
            arrived = yes = 0;
            ++generation;
            cv.notify_all();
        } else {
            const unsigned long long g = generation;
            cv.wait(lock, [&] { return generation != g; });
        }
        return result;
    }
};

template <unsigned kBatchPairs>
struct ThreadLane {
    static constexpr unsigned kBatch = kBatchPairs;
    Barrier* group;
    std::uint32_t slots[kBatch];
    bool any(bool p) const { return group->any(p); }
    void put(unsigned slot, std::uint32_t j) { slots[slot] = j; }
    std::uint32_t get(unsigned slot) const { return slots[slot]; }
};

template <class Opt, unsigned kBatch>
void expectSameBitsInLockstep(const Scene& s, std::uint32_t lanes_per_group, const char* what) {
    for (std::uint32_t first = s.nbound; first < s.n; first += lanes_per_group) {
        Barrier group;
        group.lanes = int(lanes_per_group);
        std::vector<FluidAccum> got(lanes_per_group);
        std::vector<std::thread> threads;
        for (std::uint32_t l = 0; l < lanes_per_group; ++l)
            threads.emplace_back([&, l] {
                ThreadLane<kBatch> lane{&group, {}};
                const std::uint32_t i = first + l;
                got[l] = fluidParticleForcesQueued<Opt>(i, i < s.n, s.in, s.c, s.g, lane);
            });
        for (auto& t : threads) t.join();
        for (std::uint32_t l = 0; l < lanes_per_group && first + l < s.n; ++l) {
            const FluidAccum direct = fluidParticleForces<Opt, false>(first + l, s.in, s.c, s.g);
            ASSERT_EQ(std::memcmp(&direct.ax, &got[l].ax, 6 * sizeof(float)), 0) << what << ", particle " << first + l;
        }
    }
}

}  // namespace

TEST(FluidPairQueue, LanesInLockstepGiveTheSameBits) {
    // Groups of 4 and 7 lanes (the last group partly empty): lanes run out of candidates in
    // different rounds.
    const Scene s = makeScene<2>(13);
    expectSameBitsInLockstep<FluidOptions<WendlandKernel, Viscosity::Artificial, DensityDiffusion::FourtakasFull, 2>, 3>(
        s, 4, "2D, 4 lanes, batch 3");
    expectSameBitsInLockstep<FluidOptions<WendlandKernel, Viscosity::LaminarSps, DensityDiffusion::None, 2>, 16>(
        s, 7, "2D SPS, 7 lanes, batch 16");
}

TEST(FluidPairQueue, SameBitsAsTheDirectLoop3D) { checkAllOptions<3>(11); }
TEST(FluidPairQueue, SameBitsAsTheDirectLoop2D) { checkAllOptions<2>(12); }
