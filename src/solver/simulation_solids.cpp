// SeaSpring — MIT licence.
/// \file simulation_solids.cpp
/// \brief The VCPM parts of a run's outputs and summary (see simulation.h): broken-bond counts
///        and the solid fields of the part files.
#include <cstdio>

#include "core/error.h"

#include "physics/vcpm.h"
#include "solver/simulation.h"

namespace seaspring::solver {

std::uint64_t Simulation::brokenBonds(const HostState& st) const {
    const SolidSetup& so = setup_.solid;
    std::uint64_t solid_slots = 0, clamp = 0;
    for (std::size_t k = 0; k < st.bond_broken.size(); ++k)
        if (st.bond_broken[k]) ((so.flags[k] & physics::kBondClamp) ? clamp : solid_slots) += 1;
    return solid_slots / 2 + clamp;
}

void Simulation::solidFields(const HostState& st, std::vector<float>& disp, std::vector<float>& strain,
                             std::vector<std::uint8_t>& broken, std::vector<float>& damage) const {
    const SolidSetup& so = setup_.solid;
    const std::size_t np = st.pos.size();
    disp.assign(3 * np, 0.f);
    strain.assign(np, 0.f);
    broken.assign(np, 0);
    damage.assign(np, 0.f);
    for (std::uint32_t r = 0; r < so.nsolid; ++r) {
        const std::uint32_t id = so.first_solid + r;
        const physics::Double3 p = st.pos[id];
        const Vec3d p0 = case_.particles.pos[id];
        disp[3 * id] = float(p.x - p0.x);
        disp[3 * id + 1] = float(p.y - p0.y);
        disp[3 * id + 2] = float(p.z - p0.z);
        double sum = 0;
        int intact = 0, nbroken = 0;
        for (int q = 0; q < so.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * so.nsolid + r;
            if (st.bond_broken[k]) {
                ++nbroken;
                continue;
            }
            const std::uint32_t j = (so.flags[k] & physics::kBondClamp) ? so.clamp_id[so.partner[k]]
                                                                         : so.first_solid + so.partner[k];
            double dx, dy, dz;
            const double len = physics::bondVector(p, st.pos[j], dx, dy, dz);
            sum += physics::bondStrain(len, so.rest[k]);
            ++intact;
        }
        strain[id] = intact > 0 ? float(sum / intact) : 0.f;
        broken[id] = std::uint8_t(nbroken);
        damage[id] = so.count[r] > 0 ? float(nbroken) / float(so.count[r]) : 0.f;
    }
}

}  // namespace seaspring::solver
