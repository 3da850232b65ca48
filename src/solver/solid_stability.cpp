// SeaSpring — MIT licence.
#include "solver/solid_stability.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "physics/vcpm.h"
#include "physics/vcpm_substep.h"
#include "physics/vcpm_surface.h"
#include "solver/solid_arrays.h"
#include "solver/solid_setup.h"

namespace seaspring::solver {

namespace {

using physics::Double3;

/// K u for the solid's lattice at its rest state, K = -dF/dx: central differences of the
/// solver's own force functions (physics::solidSumAt, clampSumAt, solidBondForceAt; clamp
/// nodes held), one particle per iteration of each loop (the same bits with any thread count).
class StiffnessProduct {
public:
    explicit StiffnessProduct(const SolidSetup& s) : s_(s) {
        a_.init(s);
        xp_.resize(s.nsolid);
        xm_.resize(s.nsolid);
        eps_ = 1e-7 * (s.rest.empty() ? 1.0 : s.rest[0]);
    }
    /// out = K u (u, out: 3 components per particle).
    void apply(const std::vector<double>& u, std::vector<double>& out) {
        const std::int64_t n = s_.nsolid;
        for (std::int64_t i = 0; i < n; ++i) {
            const Double3 p = s_.pos[i];
            xp_[i] = Double3{p.x + eps_ * u[3 * i], p.y + eps_ * u[3 * i + 1], p.z + eps_ * u[3 * i + 2]};
            xm_[i] = Double3{p.x - eps_ * u[3 * i], p.y - eps_ * u[3 * i + 1], p.z - eps_ * u[3 * i + 2]};
        }
        forces(xp_, fp_);
        forces(xm_, fm_);
        out.resize(u.size());
        for (std::int64_t i = 0; i < n; ++i) {
            out[3 * i] = -(fp_[i].x - fm_[i].x) / (2 * eps_);
            out[3 * i + 1] = -(fp_[i].y - fm_[i].y) / (2 * eps_);
            out[3 * i + 2] = -(fp_[i].z - fm_[i].z) / (2 * eps_);
        }
    }

private:
    void forces(const std::vector<Double3>& x, std::vector<Double3>& f) {
        physics::SolidState st = a_.state();
        st.alarm = nullptr;
        const physics::SolidBonds b = a_.bonds();
        physics::ClampNodes cn = a_.clamps();
        const std::int64_t n = b.n, nc = cn.n;
        f.resize(n);
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < n; ++i) st.sum[i] = physics::solidSumAt(std::uint32_t(i), x.data(), st, b, cn, 0.0);
#pragma omp parallel for schedule(static)
        for (std::int64_t c = 0; c < nc; ++c) cn.sum[c] = physics::clampSumAt(std::uint32_t(c), x.data(), st, b, cn, 0.0);
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < n; ++i) f[i] = physics::solidBondForceAt(std::uint32_t(i), x.data(), st, b, cn, 0.0);
    }

    const SolidSetup& s_;
    SolidArrays<HostBuffer> a_;
    std::vector<Double3> xp_, xm_, fp_, fm_;
    double eps_ = 0;
};

double comp(const physics::Double3& v, int c) { return c == 0 ? v.x : c == 1 ? v.y : v.z; }
double norm1(const physics::Double3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }
physics::Double3 unit(const physics::Double3& from, const physics::Double3& to) {
    const double dx = to.x - from.x, dy = to.y - from.y, dz = to.z - from.z;
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    return physics::Double3{dx / l, dy / l, dz / l};
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
    double r = 0;
    for (std::size_t i = 0; i < a.size(); ++i) r += a[i] * b[i];
    return r;
}

}  // namespace

std::vector<double> largestStiffnessPerBody(const SolidSetup& s, int iterations) {
    std::vector<double> out(s.materials.size(), 0.0);
    if (s.nsolid == 0) return out;
    StiffnessProduct k(s);
    const std::size_t m = 3 * std::size_t(s.nsolid);
    for (std::size_t body = 0; body < s.materials.size(); ++body) {
        // A fixed-seed start vector on this body's particles (and the plane's components in 2D).
        std::mt19937 rng(12345u + std::uint32_t(body));
        std::vector<double> v(m, 0.0), v_prev(m, 0.0), w;
        for (std::uint32_t i = 0; i < s.nsolid; ++i) {
            if (s.body[i] != body) continue;
            for (int c = 0; c < 3; ++c)
                if (!(s.dim == 2 && c == 1)) v[3 * i + c] = double(rng()) / 4294967296.0 - 0.5;
        }
        double norm = std::sqrt(dot(v, v));
        if (!(norm > 0)) continue;
        for (double& x : v) x /= norm;
        // Lanczos without reorthogonalisation: the largest Ritz value of the tridiagonal
        // matrix approaches lambda_max from below (lost orthogonality only repeats Ritz values).
        std::vector<double> alpha, beta;
        double b_prev = 0;
        for (int it = 0; it < iterations; ++it) {
            k.apply(v, w);
            const double a = dot(w, v);
            for (std::size_t j = 0; j < m; ++j) w[j] -= a * v[j] + b_prev * v_prev[j];
            alpha.push_back(a);
            const double b = std::sqrt(dot(w, w));
            if (!(b > 1e-12 * std::fabs(a))) break;  // an invariant subspace: its values are exact
            beta.push_back(b);
            v_prev.swap(v);
            for (std::size_t j = 0; j < m; ++j) v[j] = w[j] / b;
            b_prev = b;
        }
        const Eigen::Index r = Eigen::Index(alpha.size());
        Eigen::MatrixXd t = Eigen::MatrixXd::Zero(r, r);
        for (Eigen::Index i = 0; i < r; ++i) {
            t(i, i) = alpha[std::size_t(i)];
            if (i + 1 < r) t(i, i + 1) = t(i + 1, i) = beta[std::size_t(i)];
        }
        out[body] = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(t, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
    }
    return out;
}

std::vector<double> plainBulkStiffnessPerBody(const SolidSetup& s) {
    std::vector<double> out;
    for (const physics::VcpmMaterial& m : s.materials)
        out.push_back(physics::plainBulkLargestStiffness(s.dim, m.k_first, m.k_second, m.t_half));
    return out;
}

std::vector<double> eigenSubStepScales(const SolidSetup& s) {
    const std::vector<double> lambda = largestStiffnessPerBody(s, kStiffnessIterations);
    const std::vector<double> bulk = plainBulkStiffnessPerBody(s);
    std::vector<double> scales(s.materials.size(), 1.0);
    for (std::size_t b = 0; b < s.materials.size(); ++b) {
        const double body = lambda[b] * (1.0 + kStiffnessMargin);
        if (body > bulk[b]) scales[b] = std::sqrt(bulk[b] / body);
    }
    return scales;
}

std::vector<double> gershgorinSubStepScales(const SolidSetup& s) {
    const std::uint32_t n = s.nsolid;
    std::vector<double> row(3 * std::size_t(n), 0.0);  // Gershgorin row sums, (particle, component)
    auto add = [&](std::uint32_t p, const physics::Double3& v, double c_norm) {  // c |v_a| ||V||_1 on p's rows
        for (int c = 0; c < 3; ++c) row[3 * std::size_t(p) + c] += std::fabs(comp(v, c)) * c_norm;
    };
    auto partnerPos = [&](std::size_t k) {
        return (s.flags[k] & physics::kBondClamp) ? s.clamp_pos[s.partner[k]] : s.pos[s.partner[k]];
    };
    std::vector<physics::Double3> g_own(n);
    for (std::uint32_t r = 0; r < n; ++r) {
        const physics::VcpmMaterial& m = s.materials[s.body[r]];
        physics::Double3 own{0, 0, 0};  // g_r's block at r: -sum_J w u
        double g_norm = 0;              // ||g_r||_1 over the solid partners' blocks
        for (int q = 0; q < s.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * n + r;
            const bool clamp = (s.flags[k] & physics::kBondClamp) != 0;
            const physics::Double3 u = unit(s.pos[r], partnerPos(k));
            const double w = s.vw.empty() ? 1.0 : s.vw[k];
            own = physics::Double3{own.x - w * u.x, own.y - w * u.y, own.z - w * u.z};
            if (!clamp) g_norm += std::fabs(w) * norm1(u);
            // The bond's spring term k/2 b b^T, once per bond (b: -u at r, +u at a solid partner).
            if (clamp || s.partner[k] > r) {
                const double kk = physics::bondStiffness(m, s.flags[k]) * (s.kfac.empty() ? 1.0 : s.kfac[k]);
                const double b_norm = norm1(u) * (clamp ? 1.0 : 2.0);
                add(r, u, 0.5 * kk * b_norm);
                if (!clamp) add(s.partner[k], u, 0.5 * kk * b_norm);
            }
        }
        g_own[r] = own;
        // The site's volumetric term t_half/2 g g^T on r's rows and its solid partners'.
        const double c = 0.5 * std::fabs(m.t_half) * (g_norm + norm1(own));
        add(r, own, c);
        for (int q = 0; q < s.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * n + r;
            if (s.flags[k] & physics::kBondClamp) continue;
            const double w = s.vw.empty() ? 1.0 : s.vw[k];
            const physics::Double3 u = unit(s.pos[r], partnerPos(k));
            add(s.partner[k], physics::Double3{w * u.x, w * u.y, w * u.z}, c);
        }
    }
    // The rows' bending k_r c c^T per row triplet, c = (1, -2, 1) on (minus, centre, plus) in
    // every component (physics/vcpm_rows.h); rigid clamp nodes have no rows.
    for (std::uint32_t r = 0; r < n; ++r)
        for (int a = 0; a < s.row_axes; ++a) {
            std::size_t km = 0, kp = 0;
            if (!rowTripletSlots(s, r, a, km, kp)) continue;
            const bool sm = !(s.flags[km] & physics::kBondClamp), sp = !(s.flags[kp] & physics::kBondClamp);
            const double k_r = s.materials[s.body[r]].row_k;
            const double c_norm = 2.0 + (sm ? 1.0 : 0.0) + (sp ? 1.0 : 0.0);
            const physics::Double3 all{1, 1, 1};
            add(r, all, 2.0 * k_r * c_norm);
            if (sm) add(s.partner[km], all, k_r * c_norm);
            if (sp) add(s.partner[kp], all, k_r * c_norm);
        }
    // Clamp nodes' volumetric terms (unweighted sums; the node itself is rigid).
    for (std::uint32_t cn = 0; cn < s.nclamp; ++cn) {
        if (s.clamp_count[cn] == 0) continue;
        double g_norm = 0;
        for (int q = 0; q < s.clamp_count[cn]; ++q) {
            const std::uint32_t p = s.clamp_partner[std::size_t(q) * s.nclamp + cn];
            g_norm += norm1(unit(s.clamp_pos[cn], s.pos[p]));
        }
        for (int q = 0; q < s.clamp_count[cn]; ++q) {
            const std::uint32_t p = s.clamp_partner[std::size_t(q) * s.nclamp + cn];
            add(p, unit(s.clamp_pos[cn], s.pos[p]), 0.5 * std::fabs(s.materials[s.body[p]].t_half) * g_norm);
        }
    }
    // Per body: the largest row against the plain bulk site's (the stencil, unit vectors).
    std::vector<physics::Double3> stencil;
    std::vector<std::uint8_t> second;
    physics::latticeStencil(s.dim, stencil, second);
    for (physics::Double3& u : stencil) u = unit(physics::Double3{0, 0, 0}, u);
    std::vector<double> scales(s.materials.size(), 1.0), rmax(s.materials.size(), 0.0);
    for (std::uint32_t r = 0; r < n; ++r)
        for (int c = 0; c < 3; ++c) rmax[s.body[r]] = std::max(rmax[s.body[r]], row[3 * std::size_t(r) + c]);
    for (std::size_t b = 0; b < s.materials.size(); ++b) {
        const physics::VcpmMaterial& m = s.materials[b];
        std::vector<double> k;
        for (std::uint8_t sec : second) k.push_back(sec ? m.k_second : m.k_first);
        double bulk = 0;
        for (int c = 0; c < 3; ++c)
            if (!(s.dim == 2 && c == 1)) bulk = std::max(bulk, physics::plainBulkRowBound(stencil, k, m.t_half, c));
        if (rmax[b] > bulk) scales[b] = std::sqrt(bulk / rmax[b]);
    }
    return scales;
}

std::vector<double> correctedSubStepScales(const SolidSetup& s, int bound) {
    return bound == 1 ? eigenSubStepScales(s) : gershgorinSubStepScales(s);
}

}  // namespace seaspring::solver
