// SeaSpring — MIT licence.
#include "solver/solid_stability.h"

#include <algorithm>
#include <cmath>

#include "physics/vcpm.h"
#include "physics/vcpm_surface.h"
#include "solver/solid_setup.h"

namespace seaspring::solver {

namespace {

double comp(const physics::Double3& v, int c) { return c == 0 ? v.x : c == 1 ? v.y : v.z; }
double norm1(const physics::Double3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }
physics::Double3 unit(const physics::Double3& from, const physics::Double3& to) {
    const double dx = to.x - from.x, dy = to.y - from.y, dz = to.z - from.z;
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    return physics::Double3{dx / l, dy / l, dz / l};
}

}  // namespace

std::vector<double> correctedSubStepScales(const SolidSetup& s) {
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

}  // namespace seaspring::solver
