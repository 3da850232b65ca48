// SeaSpring — MIT licence.
/// \file test_physics_kernels.cpp
/// \brief Kernel normalisation and gradients (2D, 3D, Wendland, cubic), the Tait EOS, the
///        seventh root and the DDT hydrostatic term against hand values; the fluid constants of a
///        case (makeFluidConstants) against hand values; a pair's acceleration alone
///        (addPairAcceleration from -0) equals the plain products bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "physics/density_diffusion.h"
#include "physics/eos_tait.h"
#include "physics/fluid_constants.h"
#include "physics/fluid_pair_terms.h"
#include "physics/time_integration.h"
#include "physics/sph_kernels.h"
#include "physics/viscosity.h"

using namespace seaspring::physics;

namespace {

/// Integral of W over the plane (2D) or space (3D) by a midpoint rule on a fine lattice.
template <class K>
double integral(const KernelConstants& k, double h, int dim) {
    const int n = dim == 2 ? 800 : 160;
    const double d = 4.0 * h / n;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int l = 0; l < (dim == 3 ? n : 1); ++l) {
                const double x = -2 * h + (i + 0.5) * d, y = -2 * h + (j + 0.5) * d;
                const double z = dim == 3 ? -2 * h + (l + 0.5) * d : 0.0;
                const double r2 = x * x + y * y + z * z;
                if (r2 <= 4 * h * h) sum += K::value(float(r2), k);
            }
    return sum * (dim == 2 ? d * d : d * d * d);
}

template <class K>
void checkGradient(const KernelConstants& k, double h) {
    // F(r) r must equal dW/dr (central difference of W in double-step float).
    for (double q : {0.3, 0.7, 0.99, 1.01, 1.5, 1.9}) {
        const double r = q * h, e = 1e-3 * h;
        const double dwdr = (K::value(float((r + e) * (r + e)), k) - K::value(float((r - e) * (r - e)), k)) / (2 * e);
        const double f = K::gradFactor(float(r * r), k) * r;
        EXPECT_NEAR(f, dwdr, 2e-3 * std::fabs(dwdr) + 1e-6 * std::fabs(K::value(0.f, k)) / h) << "q=" << q;
    }
}

}  // namespace

TEST(Kernels, WendlandIntegratesToOne) {
    const double h = 0.02;
    EXPECT_NEAR(integral<WendlandKernel>(makeKernelConstants(h, h / 1.5, 2), h, 2), 1.0, 1e-4);
    EXPECT_NEAR(integral<WendlandKernel>(makeKernelConstants(h, h / 1.5, 3), h, 3), 1.0, 2e-3);
}

TEST(Kernels, CubicIntegratesToOne) {
    const double h = 0.02;
    EXPECT_NEAR(integral<CubicKernel>(makeKernelConstants(h, h / 1.5, 2), h, 2), 1.0, 1e-4);
    EXPECT_NEAR(integral<CubicKernel>(makeKernelConstants(h, h / 1.5, 3), h, 3), 1.0, 2e-3);
}

TEST(Kernels, GradientFactorIsDerivativeOverR) {
    const double h = 0.05;
    for (int dim : {2, 3}) {
        checkGradient<WendlandKernel>(makeKernelConstants(h, h / 1.5, dim), h);
        checkGradient<CubicKernel>(makeKernelConstants(h, h / 1.5, dim), h);
    }
}

TEST(Kernels, WendlandHandValues) {
    // 3D, h = 1: aD = 21/(16 pi); W(0) = aD; W(1) = aD * (1/2)^4 * 3; F(1) = -5 aD (1/2)^3.
    const KernelConstants k = makeKernelConstants(1.0, 1.0, 3);
    const double ad = 21.0 / (16.0 * 3.14159265358979323846);
    EXPECT_NEAR(WendlandKernel::value(0.f, k), ad, 1e-6);
    EXPECT_NEAR(WendlandKernel::value(1.f, k), ad * 3.0 / 16.0, 1e-6);
    EXPECT_NEAR(WendlandKernel::gradFactor(1.f, k), -5.0 * ad / 8.0, 1e-6);
    EXPECT_EQ(WendlandKernel::value(4.f, k), 0.f);
    EXPECT_EQ(WendlandKernel::gradFactor(4.f, k), 0.f);
}

TEST(Kernels, CubicTensileCorrectionHandValue) {
    // At r = dp, W/W(dp) = 1: correction = 0.01 p/rho^2 per positive-pressure particle.
    const double h = 1.0, dp = 1.0 / 1.2;
    const KernelConstants k = makeKernelConstants(h, dp, 3);
    const float r2 = float(dp * dp);
    const float t = CubicKernel::tensileCorrection(r2, 2000.f, 1000.f, -1000.f, 1000.f, k);
    EXPECT_NEAR(t, 0.01 * 2000.0 / 1e6 + (-0.2) * (-1000.0) / 1e6, 1e-8);
}

TEST(Eos, TaitHandValues) {
    // B = 1e5 Pa, rho0 = 1000: p(1010) = 1e5 (1.01^7 - 1).
    // Float evaluation: relative error a few 1e-6 of the pressure (1e-3f is not exact).
    EXPECT_NEAR(taitPressure7(1010.f, 1e5f, 1e-3f), 1e5 * (std::pow(1.01, 7) - 1), 0.1);
    EXPECT_EQ(taitPressure7(1000.f, 1e5f, 1e-3f), 0.f);
    EXPECT_NEAR(taitPressure7(990.f, 1e5f, 1e-3f), 1e5 * (std::pow(0.99, 7) - 1), 0.1);
    EXPECT_NEAR(taitB(30.0, 1000.0, 7.0), 900.0 * 1000.0 / 7.0, 1e-9);
}

TEST(Ddt, HydrostaticCubicIsTheSeventhRoot) {
    // rhoH = rho0 ((1 + ddtgz dz)^(1/7) - 1) over |e| = |ddtgz dz| <= 0.03 (30 times the
    // hydrostatic range over 2h), for rho0 = 1000 and ddtgz = 7 g / c0^2 at c0 = 20.
    const double rho0 = 1000, ddtgz = 7.0 * 9.81 / 400.0;
    const HydrostaticCubic k = makeHydrostaticCubic(ddtgz, rho0);
    for (double e = -0.03; e <= 0.03; e += 0.0005) {
        const float dz = float(e / ddtgz);
        const double ref = rho0 * (std::pow(1.0 + ddtgz * double(dz), 1.0 / 7.0) - 1.0);
        // Relative to the result: no cancellation near dz = 0; the series' first omitted term,
        // (65/2401) e^4 rho0, is below 2.2e-5 here.
        EXPECT_NEAR(hydrostaticDensityDifference(dz, k), ref, 3e-7 * std::fabs(ref) + 2.5e-5) << e;
    }
    EXPECT_EQ(hydrostaticDensityDifference(0.f, k), 0.f);
}

TEST(Ddt, HydrostaticTermMatchesTaitInverse) {
    // Two particles dz apart in a still column: rhoH_ab = rho_b - rho_a exactly in the Tait
    // hydrostatic profile, so the Fourtakas pair term vanishes.
    const double rho0 = 1000, g = 9.81, c0 = 30, b = c0 * c0 * rho0 / 7.0, dz = 0.02;
    const double za = 0.1, zb = za + dz, depth = 0.5;
    const double rho_a = hydrostaticDensity(rho0, b, 7, g, depth - za);
    const double rho_b = hydrostaticDensity(rho0, b, 7, g, depth - zb);
    const HydrostaticCubic hyd = makeHydrostaticCubic(rho0 * g / b, rho0);  // -rho0 g_z / B, g_z = -g
    const float dh = hydrostaticDensityDifference(float(za - zb), hyd);
    // Exact: rho0 ((1 + rho0 g dz / B)^(1/7) - 1) with sign from gz.
    const double exact = rho0 * (std::pow(1.0 + rho0 * g * (za - zb) / b, 1.0 / 7.0) - 1.0);
    EXPECT_NEAR(dh, exact, 1e-5 * std::fabs(exact));
    // Fourtakas' rhoH is referred to rho0, not rho_a: the relative error is about
    // rho0 g depth / B (3% at 0.4 m depth here).
    EXPECT_NEAR(dh, rho_b - rho_a, 0.04 * std::fabs(rho_b - rho_a));
    const float ov_r2eta = 1.f / (float(dz * dz) + 1e-6f);
    const float term = ddtFourtakasPair(float(rho_a), float(rho_b), 1.f / float(rho_b), float(za - zb),
                                        ov_r2eta, -1000.f * float(dz * dz), 0.008f, 0.0069f,
                                        float(c0), hyd).value();
    const float molteni_scale = std::fabs(ddtMolteniPair(float(rho_a), 1.f / float(rho_b), ov_r2eta,
                                                         -1000.f * float(dz * dz), 0.008f, 0.0069f,
                                                         float(c0)).value());
    EXPECT_LT(std::fabs(term), 0.05f * molteni_scale);
}

TEST(Viscosity, ArtificialOnlyWhenApproaching) {
    const PairReciprocals r = pairReciprocals(1e-4f, 4e-6f, 1000.f, 1002.f);
    EXPECT_NEAR(r.ov_r2eta, 1.0 / (1e-4 + 4e-6), 1e-6 / (1e-4 + 4e-6));
    EXPECT_NEAR(r.ov_rhosum, 1.0 / 2002.0, 1e-6 / 2002.0);
    EXPECT_NEAR(r.ov_both, 1.0 / ((1e-4 + 4e-6) * 2002.0), 1e-6 / ((1e-4 + 4e-6) * 2002.0));
    EXPECT_EQ(artificialViscosityFactor(viscDtPair(0.1f, r.ov_r2eta), r.ov_rhosum, 0.001f, 0.1f, 30, 0.02f), 0.f);
    EXPECT_EQ(artificialViscosityFactor(0.f, r.ov_rhosum, 0.001f, 0.1f, 30, 0.02f), 0.f);
    const float s = artificialViscosityFactor(viscDtPair(-0.1f, r.ov_r2eta), r.ov_rhosum, 0.001f, 0.1f, 30, 0.02f);
    // Pi = -alpha c0 h (v.r/(r^2+eta2)) / rhobar, times m_b.
    const double ref = (-0.1 * 30 * (0.02 * (-0.1 / (1e-4 + 4e-6))) / 1001.0) * 0.001;
    EXPECT_NEAR(s, ref, 1e-6 * std::fabs(ref));
}

TEST(Viscosity, LaminarFactorIsLoAndShao) {
    // s = m_b 4 nu (r . grad W) / ((r^2 + eta2)(rho_a + rho_b)), from pairReciprocals' D.
    const PairReciprocals r = pairReciprocals(1e-4f, 4e-6f, 1000.f, 1002.f);
    const float s = laminarViscosityFactor(-3.5f, r.ov_both, 0.001f, 1e-6f);
    const double ref = 0.001 * 4e-6 * -3.5 / ((1e-4 + 4e-6) * 2002.0);
    EXPECT_NEAR(s, ref, 1e-6 * std::fabs(ref));
}

TEST(Viscosity, SpsTauOfPureShear) {
    // du/dy = g: xy = g; |S| term prr = g^2; tau_xy = smag g * g / rho.
    SymTensor gv{0, 2.f, 0, 0, 0, 0};
    const SymTensor t = spsTau(gv, 1000.f, 1e-6f, 1e-7f);
    EXPECT_NEAR(t.xy, 1e-6 * 2.0 * 2.0 / 1000.0, 1e-12);
    EXPECT_NEAR(t.xx, -(1e-7 * 4.0) / 1000.0, 1e-13);
}

// VelocityGradientTerm: a pair's terms of the velocity-gradient sums are the symmetrised
// products u (x) f with u = -v_ab/rho_b and f = m_b grad W, added by fused multiply-adds: the
// diagonal ones one rounding of the sum and the product, the mixed ones (xy += ux fy + uy fx, ...)
// two, so within two roundings of the exact sum; and the same bits as those fused
// multiply-adds in that order (which the host and the GPU compute alike). Checked over random
// pairs added to random sums, with exact zeros of both signs a quarter of the time each, against
// the products in double. Broken on purpose (xy formed as ux fy + uy fy): fails.
TEST(Viscosity, VelocityGradientTermsAreTheSymmetrisedProducts) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> u(-2.f, 2.f);
    std::uniform_int_distribution<int> pick(0, 3);
    auto value = [&]() {  // a zero of either sign a quarter of the time each
        const int k = pick(rng);
        return k == 0 ? 0.f : (k == 1 ? -0.f : u(rng));
    };
    // |t - (s + a b + c d)| within one rounding of the result and one of the inner sum
    // (s + c d): at most 2^-23 (|s| + |a b| + |c d|) (0 for exact zeros).
    auto within = [](float t, double s, double ab, double cd) {
        return std::fabs(double(t) - (s + ab + cd)) <= std::ldexp(std::fabs(s) + std::fabs(ab) + std::fabs(cd), -23);
    };
    for (int p = 0; p < 200000; ++p) {
        const float dvx = value(), dvy = value(), dvz = value(), fx = value(), fy = value(), fz = value();
        const float ovrho = 1e-3f * (0.5f + 0.5f * std::fabs(u(rng)));
        const VelocityGradientTerm t = velocityGradientTerm(dvx, dvy, dvz, ovrho);
        ASSERT_EQ(t.ux, dvx * -ovrho) << p;
        ASSERT_EQ(t.uy, dvy * -ovrho) << p;
        ASSERT_EQ(t.uz, dvz * -ovrho) << p;
        const SymTensor s0{value() * 1e-3f, value() * 1e-3f, value() * 1e-3f, value() * 1e-3f, value() * 1e-3f,
                           value() * 1e-3f};
        SymTensor g = s0;
        t.addTo(g, fx, fy, fz);
        const double ux = t.ux, uy = t.uy, uz = t.uz;
        ASSERT_TRUE(within(g.xx, s0.xx, ux * fx, 0.0)) << p;
        ASSERT_TRUE(within(g.yy, s0.yy, uy * fy, 0.0)) << p;
        ASSERT_TRUE(within(g.zz, s0.zz, uz * fz, 0.0)) << p;
        ASSERT_TRUE(within(g.xy, s0.xy, ux * fy, uy * fx)) << p;
        ASSERT_TRUE(within(g.xz, s0.xz, ux * fz, uz * fx)) << p;
        ASSERT_TRUE(within(g.yz, s0.yz, uy * fz, uz * fy)) << p;
        ASSERT_EQ(g.xy, fma32(t.ux, fy, fma32(t.uy, fx, s0.xy))) << p;
    }
}

// addStressTerm: the SPS stress term st . f added row by row, the last column first, as fused
// multiply-adds; within three roundings of the exact sum. Broken on purpose (st.xz in the place
// of st.yz in the y row): fails.
TEST(Viscosity, StressTermIsTheTensorTimesTheGradient) {
    std::mt19937 rng(777);
    std::uniform_real_distribution<float> u(-2.f, 2.f);
    for (int p = 0; p < 100000; ++p) {
        const SymTensor st{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        const float f[3] = {u(rng), u(rng), u(rng)};
        const float a0[3] = {u(rng), u(rng), u(rng)};
        float a[3] = {a0[0], a0[1], a0[2]};
        addStressTerm(st, f[0], f[1], f[2], a[0], a[1], a[2]);
        const double m[3][3] = {{st.xx, st.xy, st.xz}, {st.xy, st.yy, st.yz}, {st.xz, st.yz, st.zz}};
        for (int r = 0; r < 3; ++r) {
            double ex = a0[r], mag = std::fabs(a0[r]);
            for (int k = 0; k < 3; ++k) {
                ex += m[r][k] * f[k];
                mag += std::fabs(m[r][k] * f[k]);
            }
            ASSERT_LE(std::fabs(double(a[r]) - ex), std::ldexp(mag, -22)) << p << " row " << r;
        }
        ASSERT_EQ(a[0], fma32(st.xx, f[0], fma32(st.xy, f[1], fma32(st.xz, f[2], a0[0])))) << p;
    }
}

TEST(FluidConstants, HandValues) {
    // 3D, h = 0.02, dp = 0.01, c0 = 30, rho0 = 1000, B = c0^2 rho0 / 7, g_z = -9.81.
    FluidInputs in;
    in.h = 0.02;
    in.dp = 0.01;
    in.dim = 3;
    in.cs0 = 30;
    in.b = 900.0 * 1000.0 / 7.0;
    in.rhop0 = 1000;
    in.massfluid = 1e-3;
    in.massbound = 1.5e-3;
    in.visco = 0.1;
    in.visco_bound_factor = 2;
    in.ddt_value = 0.1;
    in.gravity_z = -9.81;
    in.dt_all_particles = true;
    const FluidConstants c = makeFluidConstants(in);
    EXPECT_FLOAT_EQ(c.eta2, 4e-6f);                        // (0.1 h)^2
    EXPECT_FLOAT_EQ(c.cs0, 30.f);
    EXPECT_FLOAT_EQ(c.cteb, float(900.0 * 1000.0 / 7.0));
    EXPECT_FLOAT_EQ(c.rhop0, 1000.f);
    EXPECT_FLOAT_EQ(c.ovrhop0, 1e-3f);
    EXPECT_FLOAT_EQ(c.massfluid, 1e-3f);
    EXPECT_FLOAT_EQ(c.massbound, 1.5e-3f);
    EXPECT_FLOAT_EQ(c.visco, 0.1f);
    EXPECT_FLOAT_EQ(c.visco_bound, 0.2f);                  // x ViscoBoundFactor
    EXPECT_FLOAT_EQ(c.ddtkh, 0.004f);                      // delta 2h
    // rhoH's cubic from ddtgz = -rho0 g_z / B: c1 = rho0 ddtgz / 7, c2 = -3/49 rho0 ddtgz^2.
    const double ddtgz = 1000.0 * 9.81 * 7.0 / 900000.0;
    EXPECT_FLOAT_EQ(c.ddt_hyd.c1, float(1000.0 * ddtgz / 7.0));
    EXPECT_FLOAT_EQ(c.ddt_hyd.c2, float(-1000.0 * ddtgz * ddtgz * 3.0 / 49.0));
    EXPECT_EQ(c.dt_all_particles, 1);
    // Kernel and SPS constants: the physics/ functions of the same inputs, bit for bit.
    const KernelConstants k = makeKernelConstants(0.02, 0.01, 3);
    EXPECT_EQ(std::memcmp(&c.ker, &k, sizeof k), 0);
    EXPECT_FLOAT_EQ(c.ker.kernelsize2, 16e-4f);            // (2h)^2
    const SpsConstants sps = makeSpsConstants(0.01, 3);
    EXPECT_EQ(c.sps_smag, sps.smag);
    EXPECT_EQ(c.sps_blin, sps.blin);
    // Delta = dp/sqrt(3): smag = (0.12 Delta)^2, blin = (2/3) 0.0066 Delta^2.
    EXPECT_FLOAT_EQ(c.sps_smag, float(0.0144 * 1e-4 / 3.0));
    EXPECT_FLOAT_EQ(c.sps_blin, float(2.0 / 3.0 * 0.0066 * 1e-4 / 3.0));
    in.dt_all_particles = false;
    EXPECT_EQ(makeFluidConstants(in).dt_all_particles, 0);
}

namespace {

std::uint32_t bitsOf(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

/// The reaction on a boundary particle as it was computed before addPairAcceleration: the plain
/// products cf m (m: PairTerms) or, with SPS, the stress's rows times f with their last products
/// rounded alone, then the fused laminar term.
template <class Opt>
void plainPairAcceleration(const PairTerms& t, float& ax, float& ay, float& az) {
    if (Opt::sps) {
        ax = fma32(t.st.xx, t.mx, fma32(t.st.xy, t.my, t.st.xz * t.mz));
        ay = fma32(t.st.xy, t.mx, fma32(t.st.yy, t.my, t.st.yz * t.mz));
        az = fma32(t.st.xz, t.mx, fma32(t.st.yz, t.my, t.st.zz * t.mz));
    } else {
        ax = t.cf * t.mx;
        ay = t.cf * t.my;
        az = t.cf * t.mz;
    }
    if (Opt::visco != Viscosity::Artificial) {
        ax = fma32(t.cv, t.dvx, ax);
        ay = fma32(t.cv, t.dvy, ay);
        az = fma32(t.cv, t.dvz, az);
    }
}

template <class Opt>
void checkAccelerationFromMinusZero() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-2.f, 2.f);
    const float zeros[] = {0.f, -0.f};
    int zero_products = 0;
    for (int n = 0; n < 20000; ++n) {
        PairTerms t{};
        // Zero factors of either sign (a product of +-0 keeps its sign only without an addend).
        auto pick = [&](int k) { return (n >> k) % 7 == 0 ? zeros[(n >> (k + 3)) & 1] : u(rng); };
        t.mx = pick(0), t.my = pick(1), t.mz = pick(2), t.cf = pick(3);
        t.cv = pick(4), t.dvx = pick(5), t.dvy = pick(6), t.dvz = u(rng);
        t.st = SymTensor{pick(7), pick(8), pick(9), pick(10), pick(11), pick(12)};
        float ax = -0.f, ay = -0.f, az = -0.f, px, py, pz;
        addPairAcceleration<Opt>(t, ax, ay, az);
        plainPairAcceleration<Opt>(t, px, py, pz);
        ASSERT_EQ(bitsOf(ax), bitsOf(px)) << n;
        ASSERT_EQ(bitsOf(ay), bitsOf(py)) << n;
        ASSERT_EQ(bitsOf(az), bitsOf(pz)) << n;
        zero_products += (Opt::sps ? t.st.xz * t.mz : t.cf * t.mx) == 0.f ? 1 : 0;
    }
    EXPECT_GT(zero_products, 1000);  // signed zero products were exercised
}

}  // namespace

TEST(PairAcceleration, FromMinusZeroEqualsThePlainProducts) {
    checkAccelerationFromMinusZero<FluidOptions<WendlandKernel, Viscosity::Artificial, DensityDiffusion::None, 3>>();
    checkAccelerationFromMinusZero<FluidOptions<WendlandKernel, Viscosity::Laminar, DensityDiffusion::None, 3>>();
    checkAccelerationFromMinusZero<FluidOptions<CubicKernel, Viscosity::LaminarSps, DensityDiffusion::None, 2>>();
}

// The dt maxima keep a NaN whatever the order they are combined in (the GPU reduction's shape
// differs from the CPU's): a diverged force evaluation gives a non-finite dt on every backend,
// which stops the run within the step. Broken on purpose (the plain maxf, which drops a NaN in
// its second argument): fails.
TEST(DtMaxima, ANanWinsInEitherOrder) {
    const float nan = std::nanf("");
    seaspring::physics::DtMaxima a, b;
    a.ace2 = 4.f;
    a.vel2 = 1.f;
    a.visc = 2.f;
    b.ace2 = nan;
    b.vel2 = 3.f;
    b.visc = nan;
    const seaspring::physics::DtMaxima ab = seaspring::physics::combineDtMaxima(a, b);
    const seaspring::physics::DtMaxima ba = seaspring::physics::combineDtMaxima(b, a);
    EXPECT_TRUE(std::isnan(ab.ace2));
    EXPECT_TRUE(std::isnan(ba.ace2));
    EXPECT_TRUE(std::isnan(ab.visc));
    EXPECT_TRUE(std::isnan(ba.visc));
    EXPECT_EQ(ab.vel2, 3.f);
    EXPECT_EQ(ba.vel2, 3.f);
    EXPECT_FALSE(std::isfinite(seaspring::physics::variableDt(ab, 0.01, 20, 0.2)));
    EXPECT_FALSE(std::isfinite(seaspring::physics::variableDt(ba, 0.01, 20, 0.2)));
    // A NaN acceleration alone (a density rate that is not finite counts as one: dtMaximaAt).
    b.visc = 1.f;
    EXPECT_FALSE(std::isfinite(seaspring::physics::variableDt(seaspring::physics::combineDtMaxima(a, b), 0.01, 20, 0.2)));
    EXPECT_FALSE(std::isfinite(seaspring::physics::variableDt(seaspring::physics::combineDtMaxima(b, a), 0.01, 20, 0.2)));
}
