// SeaSpring — MIT licence.
/// \file test_vcpm_surface.cpp
/// \brief The surface correction's volumetric weights (physics/vcpm_surface.h) on lattice
///        blocks: the weighted sum S* of every site measures the trace of a uniform strain as a
///        complete site does (an isochoric strain gives S* = 0 at the surface too; without the
///        weights it does not), complete sites keep weight 1 exactly, and the weighted force
///        f_IJ = -k dl - T/2 (w_IJ S_I + w_JI S_J) is minus the gradient of the weighted energy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "physics/vcpm.h"
#include "physics/vcpm_surface.h"
#include "unit/vcpm_block.h"

using namespace seaspring::physics;
using seaspring::test::affine;
using seaspring::test::Block;
using seaspring::test::forceEnergyMismatch;
using seaspring::test::forces;
using seaspring::test::Mat3;
using seaspring::test::perturb;

namespace {

/// sum_J L_J n_J,x^2 of a complete site: (2 + 2 sqrt2) dp in 2D, (2 + 4 sqrt2) dp in 3D.
double completeAlpha(bool two_d, double dp) { return (two_d ? 2.0 + 2.0 * std::sqrt(2.0) : 2.0 + 4.0 * std::sqrt(2.0)) * dp; }

/// Fills b.vw and b.vw_partner from volumetricWeights (complete sites: 1, not computed).
void setWeights(Block& b) {
    const int max_bonds = b.two_d ? kMaxBonds2D : kMaxBonds3D;
    b.vw.assign(b.rest.size(), 1.0);
    for (std::uint32_t s = 0; s < b.n; ++s) {
        if (b.count[s] == max_bonds) continue;
        std::vector<Double3> r;
        for (int q = 0; q < b.count[s]; ++q) {
            const Double3 a = b.ref[s], c = b.ref[b.partner[b.slot(s, q)]];
            r.push_back(Double3{c.x - a.x, c.y - a.y, c.z - a.z});
        }
        const std::vector<double> w = volumetricWeights(r, b.two_d ? 2 : 3, completeAlpha(b.two_d, b.dp));
        ASSERT_EQ(w.size(), r.size()) << "site " << s << ": no isotropic weights";
        for (int q = 0; q < b.count[s]; ++q) b.vw[b.slot(s, q)] = w[std::size_t(q)];
    }
    b.vw_partner.resize(b.vw.size());
    for (std::size_t k = 0; k < b.vw.size(); ++k) b.vw_partner[k] = b.vw[b.mirror[k]];
}

}  // namespace

// The weighted tensor sum_J w_J L_J n_J (x) n_J of every site of a block is isotropic, alpha_I I
// (to rounding), with alpha_I between 0 and the complete site's alpha; a complete site's
// weights are exactly 1.
TEST(VcpmSurface, WeightsMakeEverySiteIsotropic) {
    for (bool two_d : {true, false}) {
        const double dp = 0.01, alpha = completeAlpha(two_d, dp);
        Block b(two_d, 5, 4, 4, dp, vcpmMaterial(two_d ? 2 : 3, 1e6, 0.49, 1000.0, dp, 0, 0));
        setWeights(b);
        const int max_bonds = two_d ? kMaxBonds2D : kMaxBonds3D;
        double worst = 0, wmin = 1e300, wmax = -1e300, amin = 1e300;
        std::size_t corrected = 0;
        for (std::uint32_t s = 0; s < b.n; ++s) {
            double t[3][3] = {};
            for (int q = 0; q < b.count[s]; ++q) {
                const std::uint32_t k = b.slot(s, q);
                const Double3 a = b.ref[s], c = b.ref[b.partner[k]];
                const double r[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
                const double l = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) t[i][j] += b.vw[k] * r[i] * r[j] / l;
                if (b.count[s] == max_bonds) {
                    EXPECT_EQ(b.vw[k], 1.0);
                }
                wmin = std::min(wmin, b.vw[k]);
                wmax = std::max(wmax, b.vw[k]);
            }
            corrected += b.count[s] < max_bonds;
            const double alpha_i = two_d ? 0.5 * (t[0][0] + t[2][2]) : (t[0][0] + t[1][1] + t[2][2]) / 3.0;
            amin = std::min(amin, alpha_i / alpha);
            EXPECT_LE(alpha_i, alpha * (1 + 1e-12));
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    if (two_d && (i == 1 || j == 1)) continue;
                    worst = std::max(worst, std::fabs(t[i][j] - (i == j ? alpha_i : 0.0)) / alpha);
                }
        }
        std::printf("[ weights ] %s: %zu sites corrected, w in [%.4f, %.4f], alpha_I/alpha >= %.4f, "
                    "max |T - alpha_I I|/alpha %.2e\n",
                    two_d ? "2D" : "3D", corrected, wmin, wmax, amin, worst);
        EXPECT_GT(corrected, 0u);
        EXPECT_LT(worst, 1e-12);
        EXPECT_GT(amin, 0.1);
        EXPECT_GT(wmin, -1e-12);  // no bond counts against its site's volume (measured: >= 0)
    }
}

// Under an isochoric uniform strain (tr eps = 0) every site's weighted S* vanishes, as a
// complete site's plain S does; the plain S of a face site does not (this is the stiffening
// near nu = 1/2). Under a pure dilatation every site's S* is positive, at most the complete
// site's S.
TEST(VcpmSurface, WeightedSumMeasuresTheTraceAtEverySite) {
    for (bool two_d : {true, false}) {
        const double dp = 0.01, e = 1e-7;
        Block b(two_d, 5, 4, 5, dp, vcpmMaterial(two_d ? 2 : 3, 1e6, 0.49, 1000.0, dp, 0, 0));
        const std::uint32_t centre = b.at(2, two_d ? 0 : 2, 2);
        Mat3 iso{}, dil{};
        iso[0][0] = 1.0;
        iso[2][2] = two_d ? -1.0 : -0.5;
        if (!two_d) iso[1][1] = -0.5;
        iso[0][2] = iso[2][0] = 0.3;
        for (int i = 0; i < 3; ++i) dil[i][i] = (two_d && i == 1) ? 0.0 : 1.0;
        double plain_iso = 0;
        {
            forces(b, affine(b, iso, e));  // fills b.sum, unweighted
            for (std::uint32_t s = 0; s < b.n; ++s) plain_iso = std::max(plain_iso, std::fabs(b.sum[s]));
        }
        setWeights(b);
        forces(b, affine(b, dil, e));
        const double ref = b.sum[centre];
        double dil_min = 1e300, dil_max = -1e300;
        for (std::uint32_t s = 0; s < b.n; ++s) {
            dil_min = std::min(dil_min, b.sum[s] / ref);
            dil_max = std::max(dil_max, b.sum[s] / ref);
        }
        forces(b, affine(b, iso, e));
        double weighted_iso = 0;
        for (std::uint32_t s = 0; s < b.n; ++s) weighted_iso = std::max(weighted_iso, std::fabs(b.sum[s]));
        std::printf("[ S* ] %s: isochoric max |S| plain %.3e, weighted %.3e (dilatation S %.3e); dilatation "
                    "S*/S_complete in [%.4f, %.4f]\n",
                    two_d ? "2D" : "3D", plain_iso, weighted_iso, ref, dil_min, dil_max);
        EXPECT_GT(plain_iso, 0.1 * ref);  // the plain sums of face sites see the isochoric strain
        EXPECT_LT(weighted_iso, 1e-5 * ref);  // second order in e (1e-7) and rounding
        EXPECT_GT(dil_min, 0.1);
        EXPECT_LT(dil_max, 1.0 + 1e-6);
    }
}

// With the weights, the force of vcpm.h (w_IJ S_I + w_JI S_J) is minus the gradient of
// U = sum_I [1/2 sum_J k dl^2 + 1/2 T (sum_J w_IJ dl_IJ)^2] (central differences), for nu on
// both sides of 1/4 (T changes sign) and near 1/2.
TEST(VcpmSurface, WeightedForceIsMinusEnergyGradient) {
    for (bool two_d : {true, false})
        for (double nu : {0.1, 0.3, 0.49}) {
            const double dp = 0.01;
            Block b(two_d, 4, 3, 4, dp, vcpmMaterial(two_d ? 2 : 3, 1e6, nu, 1000.0, dp, 0, 0));
            setWeights(b);
            const std::vector<Double3> x = seaspring::test::randomlyDeformed(b, 0.01, 0.01 * dp, 7);
            const double rel = forceEnergyMismatch(b, x);
            std::printf("[ weighted energy ] %s nu=%.2f  max |F + dU/dx| / max|F| = %.2e\n", two_d ? "2D" : "3D", nu,
                        rel);
            EXPECT_LT(rel, 1e-6);
        }
}

// The rows' own bending (physics/vcpm_rows.h, VcpmRowBending): the force of vcpm.h's passes is
// minus the gradient of the independent energy (vcpm_block.h, which finds the triplets from
// the lattice sites), with and without the volumetric weights, after a bond broke (its two
// triplets drop on both sides), and the curvatures vanish under a uniform strain plus a
// rotation (the term leaves the patch test alone).
TEST(VcpmSurface, RowBendingForceIsMinusEnergyGradient) {
    for (bool two_d : {true, false})
        for (bool weights : {false, true}) {
            const double dp = 0.01, E = 1e6, nu = 0.3;
            Block b(two_d, 5, 4, 5, dp, vcpmMaterial(two_d ? 2 : 3, E, nu, 1000.0, dp, 0, 0));
            if (weights) setWeights(b);
            b.setRows(rowBendingStiffness(two_d ? 2 : 3, latticeUniaxialModulus(two_d ? 2 : 3, E, nu), dp));
            const std::vector<Double3> x = seaspring::test::randomlyDeformed(b, 0.01, 0.02 * dp, 11);
            const double rel = forceEnergyMismatch(b, x);
            // A broken first-neighbour bond in the middle (both slots, as both ends decide alike).
            const std::uint32_t s0 = b.at(2, two_d ? 0 : 1, 2);
            for (int q = 0; q < b.count[s0]; ++q) {
                const std::uint32_t k = b.slot(s0, q);
                if (b.partner[k] == b.at(3, two_d ? 0 : 1, 2)) b.broken[k] = b.broken[b.mirror[k]] = 1;
            }
            const double rel_broken = forceEnergyMismatch(b, x);
            std::printf("[ rows' bending ] %s, weights %d: max |F + dU/dx| / max|F| = %.2e, with a broken bond %.2e\n",
                        two_d ? "2D" : "3D", int(weights), rel, rel_broken);
            EXPECT_LT(rel, 1e-6);
            EXPECT_LT(rel_broken, 1e-6);
        }
}

TEST(VcpmSurface, RowCurvatureVanishesUnderUniformStrainAndRotation) {
    for (bool two_d : {true, false}) {
        const double dp = 0.01;
        Block b(two_d, 5, 4, 5, dp, vcpmMaterial(two_d ? 2 : 3, 1e6, 0.3, 1000.0, dp, 0, 0));
        b.setRows(1e5);
        const double c = std::cos(0.7), s = std::sin(0.7);
        Mat3 e = two_d ? Mat3{{{1.03 * c, 0, 0.02 - s}, {0, 1, 0}, {s, 0, 0.98 * c}}}
                       : Mat3{{{1.03 * c, -s, 0.01}, {s, 0.99 * c, 0.02}, {0.015, 0, 0.98}}};
        std::vector<Double3> x = affine(b, e, 1.0, 0.0);
        forces(b, x);
        double dmax = 0;
        for (const Double3& d : b.row_d) dmax = std::max(dmax, seaspring::test::norm(d));
        std::printf("[ rows' bending ] %s: largest |d| under a uniform strain and rotation %.2e dp\n", two_d ? "2D" : "3D",
                    dmax / dp);
        EXPECT_LT(dmax, 1e-12 * dp);
    }
}
