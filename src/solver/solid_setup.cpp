// SeaSpring — MIT licence.
/// \file solid_setup.cpp
#include "solver/solid_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/error.h"
#include "core/format.h"
#include "physics/blowup_bounds.h"
#include "physics/solid_contact.h"
#include "physics/vcpm_substep.h"
#include "physics/vcpm_surface.h"
#include "solver/solid_stability.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

SolidSetup makeSolidSetup(const SolverCase& c) {
    SolidSetup s;
    if (c.nsolid == 0 || !c.bonds) return s;
    const BondNetwork& net = *c.bonds;
    const ParticleSet& ps = c.particles;
    const int dim = c.constants.dimensions;
    const double dp = c.constants.dp;
    s.dim = dim;
    s.first_solid = net.first_solid;
    s.nsolid = c.nsolid;
    s.max_bonds = dim == 3 ? physics::kMaxBonds3D : physics::kMaxBonds2D;
    const std::uint32_t n = s.nsolid, first = s.first_solid;

    // Materials, one per body, and the body of each particle (by global MK).
    std::map<std::uint16_t, std::uint16_t> body_of_mk;
    double dt = 1e300;
    for (std::size_t b = 0; b < c.solids.size(); ++b) {
        const SolidBody& sb = c.solids[b];
        body_of_mk[sb.mk] = std::uint16_t(b);
        const std::string model = model::constitModelProblem(sb.constitmodel, dim);
        if (!model.empty()) throwInputError(c.xml_path, sb.line, "<solid mkbound=\"" + std::to_string(sb.mkbound) + "\"> " + model);
        // The lattice is plane strain in 2D; a plane-stress sheet is the plane-strain material of
        // the same in-plane response (physics::planeStressEquivalent). Damping keeps the body's E.
        const bool plane_stress = model::effectiveConstitModel(sb, dim) == 2;
        double young = sb.youngmod, poisson = sb.poissratio;
        if (plane_stress) physics::planeStressEquivalent(sb.youngmod, sb.poissratio, young, poisson);
        physics::VcpmMaterial mat = physics::vcpmMaterial(dim, young, poisson, sb.density, dp, sb.damping, sb.critstretch);
        mat.damp_rate = physics::vcpmMaterial(dim, sb.youngmod, sb.poissratio, sb.density, dp, sb.damping,
                                              sb.critstretch).damp_rate;
        const physics::VcpmElastic el = physics::vcpmElastic(young, poisson, sb.density);
        mat.max_speed = physics::solidSpeedBound(el.wave_speed, c.constants.speedsound);
        s.materials.push_back(mat);
        s.poisson.push_back(poisson);
        s.lattice_young.push_back(young);
        s.elastic_dt.push_back(physics::vcpmTimeStep(c.params.vcpm_dt_coef, dp, el.wave_speed));
        s.dt_scale.push_back(1.0);
        dt = std::min(dt, s.elastic_dt.back());
        const physics::VcpmMaterial& m = s.materials.back();
        s.body_lines.push_back("solid mkbound=" + std::to_string(sb.mkbound) + ": rho " + shortText(sb.density, 6) +
                               ", E " + shortText(sb.youngmod, 6) + ", nu " + shortText(sb.poissratio, 6) +
                               (dim == 2 ? (plane_stress ? ", plane stress" : ", plane strain") : std::string()) + ", c_S " +
                               shortText(el.wave_speed, 6) + " m/s, k " + shortText(m.k_first, 6) +
                               (dim == 2 ? "/" + shortText(m.k_second, 6) : std::string()) + ", T " +
                               shortText(2 * m.t_half, 6) + ", damping rate " + shortText(m.damp_rate, 6) + " 1/s" +
                               (sb.critstretch > 0 ? ", breaks at stretch " + shortText(sb.critstretch, 6) : ""));
    }
    // Contact (physics/solid_contact.h): its sub-step limit for a pair of particles of the same
    // body (half the mass: the stiffest case) and against a wall.
    if (c.params.vcpm_contact) {
        s.contact_on = true;
        s.contact.range = dp;
        s.contact.list_range = 1.5 * dp;
        s.contact.stiffness = c.params.vcpm_contact_stiffness;
        s.contact.damping = c.params.vcpm_contact_damping;
        s.contact.friction = c.params.vcpm_contact_friction;
        s.contact_cap = dim == 3 ? 32u : 16u;
        double dt_contact = 1e300;
        for (const physics::VcpmMaterial& m : s.materials)
            dt_contact = std::min(dt_contact, physics::contactTimeStep(0.5 / m.inv_mass,
                                                                      physics::contactStiffness(m, s.contact.stiffness)));
        s.contact_dt = dt_contact;
        if (dt_contact < dt) dt = dt_contact;
        s.body_lines.push_back("contact: r_c = dp, k = " + shortText(s.contact.stiffness, 6) + " k_1, damping " +
                               shortText(s.contact.damping, 6) + " of critical, friction " + shortText(s.contact.friction, 6) +
                               ", sub-step limit " + shortText(dt_contact, 6) + " s");
    }
    s.dt = dt;
    const bool force_at_start = physics::predictorForceUsed(s.materials.data(), s.materials.size(), s.contact_on);
    const bool sums_at_start = physics::startSumsUsed(s.materials.data(), s.materials.size());
    s.body_lines.push_back(force_at_start ? "sub-step: 4 passes (damping or contact read the predictor's velocity)"
                           : sums_at_start ? "sub-step: 3 passes (the predictor's force changes nothing; its sums decide breakage)"
                                           : "sub-step: 2 passes (the predictor's force changes nothing: undamped, unbreakable, "
                                             "no contact)");
    // Solid particles beyond the domain by more than the kernel support are frozen (vcpm.h).
    s.keep = physics::solidKeepBox(physics::Double3{c.domain_min.x, c.domain_min.y, c.domain_min.z},
                                   physics::Double3{c.domain_max.x, c.domain_max.y, c.domain_max.z},
                                   2.0 * c.constants.h);
    s.body.resize(n);
    s.pos.resize(n);
    s.vel.resize(n);
    s.mass.resize(n);
    for (std::uint32_t k = 0; k < n; ++k) {
        const std::uint32_t id = first + k;
        const auto it = body_of_mk.find(ps.mk[id]);
        if (it == body_of_mk.end())
            throwInputError(c.xml_path, 0, "solid particle " + std::to_string(id) + " has MK " +
                                               std::to_string(ps.mk[id]) + ", which no <vcpmsolids><solid> declares");
        s.body[k] = it->second;
        s.pos[k] = physics::Double3{ps.pos[id].x, ps.pos[id].y, ps.pos[id].z};
        s.vel[k] = physics::Double3{ps.vel[id].x, ps.vel[id].y, ps.vel[id].z};
        const SolidBody& sb = c.solids[it->second];
        s.mass[k] = physics::vcpmParticleMass(dim, sb.density, dp);
    }

    // Point loads: on the particle of the body nearest to the point (initial positions).
    for (std::size_t b = 0; b < c.solids.size(); ++b)
        for (const SolidBody::Load& l : c.solids[b].loads) {
            std::uint32_t best = n;
            double best_d2 = 0;
            for (std::uint32_t k = 0; k < n; ++k) {
                if (s.body[k] != b) continue;
                const double dx = s.pos[k].x - l.point.x, dy = s.pos[k].y - l.point.y, dz = s.pos[k].z - l.point.z;
                const double d2 = dx * dx + dy * dy + dz * dz;
                if (best == n || d2 < best_d2) {
                    best = k;
                    best_d2 = d2;
                }
            }
            if (best == n)
                throwInputError(c.xml_path, l.line, "<pointload>: solid mkbound=" + std::to_string(c.solids[b].mkbound) +
                                                         " has no particles");
            if (s.load_force.empty()) {
                s.load_force.assign(n, physics::Double3{0, 0, 0});
                s.load_rate.assign(n, physics::Double3{0, 0, 0});
            }
            physics::Double3& f = s.load_force[best];
            physics::Double3& r = s.load_rate[best];
            f = physics::Double3{f.x + l.force.x, f.y + l.force.y, f.z + l.force.z};
            r = physics::Double3{r.x + l.rate.x, r.y + l.rate.y, r.z + l.rate.z};
            s.body_lines.push_back("point load on solid particle " + std::to_string(first + best) + " at (" +
                                   shortText(s.pos[best].x, 6) + ", " + shortText(s.pos[best].y, 6) + ", " + shortText(s.pos[best].z, 6) +
                                   "): F = (" + shortText(l.force.x, 6) + ", " + shortText(l.force.y, 6) + ", " + shortText(l.force.z, 6) +
                                   ") + (" + shortText(l.rate.x, 6) + ", " + shortText(l.rate.y, 6) + ", " + shortText(l.rate.z, 6) + ") t N");
        }

    // Moving boundary ids -> motion object (for clamp nodes on a moving boundary).
    std::map<std::uint32_t, std::int16_t> object_of_id;
    for (const MkBlock& blk : c.blocks) {
        if (blk.type != ParticleType::Moving) continue;
        for (std::size_t o = 0; o < c.motion.objects.size(); ++o)
            if (c.motion.objects[o].mkbound == blk.mk_local)
                for (std::uint32_t k = 0; k < blk.count; ++k) object_of_id[blk.begin + k] = std::int16_t(o);
    }

    // Bonds: padded slot-major; clamp partners become clamp-node indices.
    const std::size_t slots = std::size_t(s.max_bonds) * n;
    s.count.assign(n, 0);
    s.partner.assign(slots, 0);
    s.rest.assign(slots, 0.0);
    s.flags.assign(slots, 0);
    std::map<std::uint32_t, std::uint32_t> clamp_index;  // particle id -> clamp node
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> clamp_bonds;  // (solid, slot)
    for (std::uint32_t r = 0; r < n; ++r) {
        const std::uint32_t b0 = net.offset[r], b1 = net.offset[r + 1];
        if (b1 - b0 > std::uint32_t(s.max_bonds))
            throw Error(c.h5_path + ": solid particle " + std::to_string(first + r) + " has " +
                        std::to_string(b1 - b0) + " bonds (at most " + std::to_string(s.max_bonds) + ")");
        s.count[r] = std::uint8_t(b1 - b0);
        for (std::uint32_t q = 0; q < b1 - b0; ++q) {
            const std::uint32_t src = b0 + q;
            const std::size_t k = std::size_t(q) * n + r;
            const std::uint32_t j = net.neighbour[src];
            s.rest[k] = net.rest_length[src];
            std::uint8_t f = (net.kind[src] & BondSecond) ? physics::kBondSecond : 0;
            if (net.kind[src] & BondClampFlag) {
                f |= physics::kBondClamp;
                auto it = clamp_index.find(j);
                if (it == clamp_index.end()) {
                    it = clamp_index.emplace(j, std::uint32_t(clamp_index.size())).first;
                    clamp_bonds.emplace_back();
                }
                s.partner[k] = it->second;
                clamp_bonds[it->second].push_back({r, std::uint32_t(k)});
                ++s.clamp_bonds;
            } else {
                if (j < first || j - first >= n)
                    throw Error(c.h5_path + ": bond of solid particle " + std::to_string(first + r) +
                                " reaches particle " + std::to_string(j) + ", which is not a solid particle");
                s.partner[k] = j - first;
                if (j > first + r) ++s.bonds;
            }
            s.flags[k] = f;
        }
    }

    // Clamp nodes in order of first appearance (deterministic).
    s.nclamp = std::uint32_t(clamp_index.size());
    for (const auto& l : clamp_bonds) s.clamp_max = std::max(s.clamp_max, int(l.size()));
    s.clamp_count.assign(s.nclamp, 0);
    s.clamp_partner.assign(std::size_t(s.clamp_max) * s.nclamp, 0);
    s.clamp_slot.assign(std::size_t(s.clamp_max) * s.nclamp, 0);
    s.clamp_id.assign(s.nclamp, 0);
    s.clamp_pos.resize(s.nclamp);
    s.clamp_object.assign(s.nclamp, -1);
    for (const auto& [id, node] : clamp_index) {
        s.clamp_id[node] = id;
        s.clamp_pos[node] = physics::Double3{ps.pos[id].x, ps.pos[id].y, ps.pos[id].z};
        const auto o = object_of_id.find(id);
        if (o != object_of_id.end()) s.clamp_object[node] = o->second;
        const auto& l = clamp_bonds[node];
        s.clamp_count[node] = std::uint8_t(l.size());
        for (std::size_t q = 0; q < l.size(); ++q) {
            const std::size_t k = q * s.nclamp + node;
            s.clamp_partner[k] = l[q].first;
            s.clamp_slot[k] = l[q].second;
        }
    }
    if (c.params.vcpm_surface_correction && c.params.vcpm_row_bending) rowBending(s, dp);
    if (c.params.vcpm_surface_correction) surfaceCorrection(s, c.params.vcpm_substep_bound);
    return s;
}

void rowBending(SolidSetup& s, double dp) {
    const std::uint32_t n = s.nsolid;
    s.row_axes = s.dim == 3 ? 3 : 2;
    s.row_slot.assign(std::size_t(2 * s.row_axes) * n, physics::kNoRowSlot);
    for (std::uint32_t r = 0; r < n; ++r)
        for (int q = 0; q < s.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * n + r;
            if (s.flags[k] & physics::kBondSecond) continue;
            const physics::Double3 pj = (s.flags[k] & physics::kBondClamp) ? s.clamp_pos[s.partner[k]] : s.pos[s.partner[k]];
            const double v[3] = {pj.x - s.pos[r].x, pj.y - s.pos[r].y, pj.z - s.pos[r].z};
            int d = 0;  // the lattice axis of a first-neighbour bond: its largest component
            for (int e = 1; e < 3; ++e)
                if (std::fabs(v[e]) > std::fabs(v[d])) d = e;
            const int a = s.dim == 2 ? (d == 2 ? 1 : 0) : d;
            s.row_slot[std::size_t(2 * a + (v[d] > 0 ? 1 : 0)) * n + r] = std::uint8_t(q);
        }
    for (std::size_t b = 0; b < s.materials.size(); ++b) {
        // The lattice's own material (plane stress: its plane-strain equivalent, whose uniaxial
        // modulus is the sheet's E).
        const double young = s.lattice_young[b], nu = s.poisson[b];
        s.materials[b].row_k = physics::rowBendingStiffness(s.dim, physics::latticeUniaxialModulus(s.dim, young, nu), dp);
        if (b < s.body_lines.size()) s.body_lines[b] += ", rows' bending k_r " + shortText(s.materials[b].row_k, 6);
    }
}

void surfaceCorrection(SolidSetup& s, int substep_bound) {
    const std::uint32_t n = s.nsolid;
    const int dim = s.dim;
    // The rest vector and stiffness of each bond of particle r.
    auto bondsOf = [&](std::uint32_t r, std::vector<physics::Double3>& rv, std::vector<double>& kv) {
        rv.clear();
        kv.clear();
        const physics::VcpmMaterial& m = s.materials[s.body[r]];
        for (int q = 0; q < s.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * n + r;
            const physics::Double3 pj =
                (s.flags[k] & physics::kBondClamp) ? s.clamp_pos[s.partner[k]] : s.pos[s.partner[k]];
            rv.push_back(physics::Double3{pj.x - s.pos[r].x, pj.y - s.pos[r].y, pj.z - s.pos[r].z});
            kv.push_back(physics::bondStiffness(m, s.flags[k]));
        }
    };
    // The bulk energies per body and axis, from the full stencil at the lattice spacing.
    std::vector<physics::Double3> stencil;
    std::vector<std::uint8_t> second;
    physics::latticeStencil(dim, stencil, second);
    const double dp = s.rest.empty() ? 1.0 : [&] {
        for (std::size_t k = 0; k < s.rest.size(); ++k)
            if (!(s.flags[k] & physics::kBondSecond) && s.rest[k] > 0) return s.rest[k];
        return 1.0;
    }();
    // The lateral strain of a uniaxial stress: nu/(1-nu) in 2D plane strain, nu in 3D.
    auto lateral = [&](std::size_t b) {
        const double nu = s.poisson[b];
        return dim == 2 ? nu / (1.0 - nu) : nu;
    };
    std::vector<physics::Double3> bulk(s.materials.size());
    for (std::size_t b = 0; b < s.materials.size(); ++b) {
        std::vector<physics::Double3> rv;
        std::vector<double> kv;
        for (std::size_t q = 0; q < stencil.size(); ++q) {
            rv.push_back(physics::Double3{stencil[q].x * dp, stencil[q].y * dp, stencil[q].z * dp});
            kv.push_back(second[q] ? s.materials[b].k_second : s.materials[b].k_first);
        }
        double e[3];
        for (int d = 0; d < 3; ++d) {
            double p, v;
            physics::uniformStrainEnergy(rv, kv, s.materials[b].t_half, d, lateral(b), dim, p, v);
            e[d] = p + v;
        }
        bulk[b] = physics::Double3{e[0], e[1], e[2]};
    }
    // The volumetric weights of each site (1 for a complete site): its S* measures tr(eps) alone.
    std::vector<physics::Double3> rv;
    std::vector<double> kv;
    double alpha = 0;  // sum_J L_J n_J,x^2 of a complete site (the stencil)
    for (std::size_t q = 0; q < stencil.size(); ++q) {
        const physics::Double3 u = stencil[q];
        alpha += u.x * u.x / std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z) * dp;
    }
    std::vector<std::vector<double>> site_w(n);
    s.vw.assign(s.rest.size(), 1.0);
    s.vw_partner.assign(s.rest.size(), 1.0);
    for (std::uint32_t r = 0; r < n; ++r) {
        if (s.count[r] == s.max_bonds) continue;
        bondsOf(r, rv, kv);
        site_w[r] = physics::volumetricWeights(rv, dim, alpha);
        for (std::size_t q = 0; q < site_w[r].size(); ++q) s.vw[q * n + r] = site_w[r][q];
    }
    for (std::uint32_t r = 0; r < n; ++r)  // the mirror slot's weight (a clamp node's: 1)
        for (int q = 0; q < s.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * n + r;
            if (s.flags[k] & physics::kBondClamp) continue;
            const std::uint32_t j = s.partner[k];
            for (int p = 0; p < s.count[j]; ++p) {
                const std::size_t m = std::size_t(p) * n + j;
                if (!(s.flags[m] & physics::kBondClamp) && s.partner[m] == r) s.vw_partner[k] = s.vw[m];
            }
        }
    // g per particle and axis (1 for a complete site, and along y in 2D).
    std::vector<physics::Double3> g(n, physics::Double3{1, 1, 1});
    for (std::uint32_t r = 0; r < n; ++r) {
        if (s.count[r] == s.max_bonds) continue;
        bondsOf(r, rv, kv);
        double f[3] = {1, 1, 1};
        const physics::Double3 w = bulk[s.body[r]];
        const double wd[3] = {w.x, w.y, w.z};
        for (int d = 0; d < 3; ++d) {
            if (dim == 2 && d == 1) continue;
            double p, v;
            physics::uniformStrainEnergy(rv, kv, s.materials[s.body[r]].t_half, d, lateral(s.body[r]), dim, p, v, site_w[r]);
            f[d] = physics::surfaceFactor(wd[d], p, v);
        }
        g[r] = physics::Double3{f[0], f[1], f[2]};
    }
    s.kfac.assign(s.rest.size(), 1.0);
    const physics::Double3 one{1, 1, 1};
    for (std::uint32_t r = 0; r < n; ++r) {
        bondsOf(r, rv, kv);
        for (int q = 0; q < s.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * n + r;
            const bool clamp = (s.flags[k] & physics::kBondClamp) != 0;
            const physics::Double3 gj = clamp ? one : g[s.partner[k]];
            const physics::Double3 v = rv[q];
            const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
            s.kfac[k] = physics::bondSurfaceFactor(physics::Double3{v.x / l, v.y / l, v.z / l}, g[r], gj);
            if (clamp) s.kfac[k] *= physics::kClampBondFactor;
        }
    }
    // The corrected lattice's sub-step (solid_stability.h), with contact's limit kept.
    s.dt_scale = correctedSubStepScales(s, substep_bound);
    double dt = s.contact_on ? s.contact_dt : 1e300;
    for (std::size_t b = 0; b < s.materials.size(); ++b) {
        dt = std::min(dt, s.elastic_dt[b] * s.dt_scale[b]);
        if (b < s.body_lines.size())
            s.body_lines[b] += ", surface correction (sub-step x " + shortText(s.dt_scale[b], 4) + ")";
    }
    s.dt = dt;
}

std::vector<std::uint8_t> brokenPerParticle(const SolidSetup& s, const std::vector<std::uint8_t>& broken) {
    std::vector<std::uint8_t> out(s.nsolid, 0);
    for (std::uint32_t r = 0; r < s.nsolid; ++r)
        for (int q = 0; q < s.count[r]; ++q) out[r] = std::uint8_t(out[r] + (broken[std::size_t(q) * s.nsolid + r] ? 1 : 0));
    return out;
}

}  // namespace seaspring::solver
