// SeaSpring — MIT licence.
/// \file coupling_ledger.cpp
#include "solver/coupling_ledger.h"

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.h"
#include "io/checkpoint_file.h"
#include "physics/vcpm.h"

namespace seaspring::solver {

LedgerRow ledgerRow(double time, const HostState& st, const SolidSetup& so, const std::vector<Vec3d>& pos0,
                    std::uint32_t first_fluid, double fluid_mass, const physics::Double3& g,
                    const std::vector<physics::Double3>& boundary_force) {
    LedgerRow r;
    r.time = time;
    for (std::uint32_t i = 0; i < so.first_solid && i < boundary_force.size(); ++i) {
        r.wall_force.x += boundary_force[i].x;
        r.wall_force.y += boundary_force[i].y;
        r.wall_force.z += boundary_force[i].z;
    }
    for (std::size_t i = first_fluid; i < st.pos.size(); ++i) {
        if (st.excl[i] != physics::kActive) continue;
        const physics::Float4 v = st.velrho[i];
        r.fluid_momentum.x += fluid_mass * v.x;
        r.fluid_momentum.y += fluid_mass * v.y;
        r.fluid_momentum.z += fluid_mass * v.z;
        r.fluid_kinetic += 0.5 * fluid_mass * (double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    }
    for (std::uint32_t s = 0; s < so.nsolid; ++s) {
        const std::uint32_t id = so.first_solid + s;
        const double m = so.mass[s];
        const physics::Double3 v = st.solid_vel[s], f = st.solid_force[s], j = st.solid_impulse[s];
        r.solid_momentum.x += m * v.x;
        r.solid_momentum.y += m * v.y;
        r.solid_momentum.z += m * v.z;
        r.kinetic += 0.5 * m * (v.x * v.x + v.y * v.y + v.z * v.z);
        r.fluid_force.x += f.x;
        r.fluid_force.y += f.y;
        r.fluid_force.z += f.z;
        r.impulse.x += j.x;
        r.impulse.y += j.y;
        r.impulse.z += j.z;
        r.work += st.solid_work[s];
        if (!st.contact_work.empty()) {
            r.contact = true;
            const physics::Double3 c = st.contact_impulse[s];
            r.contact_impulse.x += c.x;
            r.contact_impulse.y += c.y;
            r.contact_impulse.z += c.z;
            r.contact_work += st.contact_work[s];
        }
        const physics::Double3 p = st.pos[id];
        r.potential -= m * (g.x * (p.x - pos0[id].x) + g.y * (p.y - pos0[id].y) + g.z * (p.z - pos0[id].z));
        // U = sum_I [1/2 sum_J k dl^2 + 1/2 T (sum_J w dl)^2] over intact bonds (each seen from I; vcpm.h;
        // k with the surface correction's factor, w its volumetric weight, 1 without it).
        const physics::VcpmMaterial& mat = so.materials[so.body[s]];
        double sum = 0, springs = 0;
        for (int q = 0; q < so.count[s]; ++q) {
            const std::size_t k = std::size_t(q) * so.nsolid + s;
            if (st.bond_broken[k]) continue;
            const bool clamp = (so.flags[k] & physics::kBondClamp) != 0;
            const std::uint32_t j_id = clamp ? so.clamp_id[so.partner[k]] : so.first_solid + so.partner[k];
            double dx, dy, dz;
            const double dl = physics::halfElongation(physics::bondVector(p, st.pos[j_id], dx, dy, dz), so.rest[k]);
            const double kb = physics::bondStiffness(mat, so.flags[k]) * (so.kfac.empty() ? 1.0 : so.kfac[k]);
            springs += physics::bondSpringEnergy(kb, dl, clamp);
            sum += so.vw.empty() ? dl : so.vw[k] * dl;
        }
        r.elastic += springs + physics::siteVolumetricEnergy(mat.t_half, sum);
        // The rows' bending, 1/2 k_r |d|^2 per row triplet centred at s (physics/vcpm_rows.h).
        for (int a = 0; a < so.row_axes; ++a) {
            std::size_t km = 0, kp = 0;
            if (!rowTripletSlots(so, s, a, km, kp) || st.bond_broken[km] || st.bond_broken[kp]) continue;
            auto partnerId = [&](std::size_t k) {
                return (so.flags[k] & physics::kBondClamp) ? so.clamp_id[so.partner[k]] : so.first_solid + so.partner[k];
            };
            r.elastic += physics::rowBendingEnergy(
                mat.row_k, physics::rowCurvature(st.pos[partnerId(km)], p, st.pos[partnerId(kp)]));
        }
    }
    // The clamp nodes' volumetric terms 1/2 T S_c^2 (T of the body they hold).
    for (std::uint32_t c = 0; c < so.nclamp; ++c) {
        if (so.clamp_count[c] == 0) continue;
        const physics::Double3 p = st.pos[so.clamp_id[c]];
        double sum = 0;
        for (int q = 0; q < so.clamp_count[c]; ++q) {
            const std::size_t k = std::size_t(q) * so.nclamp + c;
            const std::uint32_t slot = so.clamp_slot[k];
            if (st.bond_broken[slot]) continue;
            double dx, dy, dz;
            sum += physics::halfElongation(
                physics::bondVector(p, st.pos[so.first_solid + so.clamp_partner[k]], dx, dy, dz), so.rest[slot]);
        }
        r.elastic += physics::siteVolumetricEnergy(so.materials[so.body[so.clamp_partner[c]]].t_half, sum);
    }
    return r;
}

LedgerFile::LedgerFile(const std::string& outdir, long long resume_offset, bool contact)
    : path_((std::filesystem::path(outdir) / "ledger.csv").string()) {
    const bool cont = resume_offset >= 0 && io::cutForResume(path_, resume_offset);
    f_.open(path_, cont ? std::ios::app : std::ios::trunc);
    if (!f_) throw Error(path_ + ": cannot create the coupling ledger");
    if (cont) return;
    f_ << "time;fluid_px;fluid_py;fluid_pz;solid_px;solid_py;solid_pz;force_x;force_y;force_z;"
          "impulse_x;impulse_y;impulse_z;work;solid_kinetic;solid_elastic;solid_potential;fluid_kinetic;"
          "wall_fx;wall_fy;wall_fz"
       << (contact ? ";contact_impulse_x;contact_impulse_y;contact_impulse_z;contact_work" : "") << "\n";
}

void LedgerFile::add(const LedgerRow& r) {
    char line[768];
    std::snprintf(line, sizeof line,
                  "%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;"
                  "%.9g\n",
                  r.time, r.fluid_momentum.x, r.fluid_momentum.y, r.fluid_momentum.z, r.solid_momentum.x,
                  r.solid_momentum.y, r.solid_momentum.z, r.fluid_force.x, r.fluid_force.y, r.fluid_force.z,
                  r.impulse.x, r.impulse.y, r.impulse.z, r.work, r.kinetic, r.elastic, r.potential, r.fluid_kinetic,
                  r.wall_force.x, r.wall_force.y, r.wall_force.z);
    if (r.contact) {
        const std::size_t len = std::strlen(line) - 1;  // before the newline
        std::snprintf(line + len, sizeof line - len, ";%.9g;%.9g;%.9g;%.9g\n", r.contact_impulse.x, r.contact_impulse.y,
                      r.contact_impulse.z, r.contact_work);
    }
    f_ << line << std::flush;
    if (!f_) throw Error(path_ + ": cannot write the coupling ledger");
}

}  // namespace seaspring::solver
