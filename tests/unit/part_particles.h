// SeaSpring — MIT licence.
/// \file part_particles.h
/// \brief Tests: particle arrays that own the memory an io::PartFrame points into, filled one
///        particle at a time, for tests that write part files of their own.
#pragma once

#include <cstdint>
#include <vector>

#include "core/particle_set.h"
#include "io/part_output.h"

namespace seaspring::test {

struct PartParticles {
    std::vector<double> pos;
    std::vector<float> vel, rhop, press, mass;
    std::vector<std::uint32_t> id;
    std::vector<std::uint8_t> type, excluded;
    std::vector<std::uint16_t> mk;
    io::PartConstants constants;

    /// Appends a particle with the next id (pressure 0).
    void add(double x, double y, double z, float vx, float vy, float vz, float rho, float m, ParticleType t,
             std::uint16_t mk_value, std::uint8_t excl = 0) {
        id.push_back(std::uint32_t(id.size()));
        pos.insert(pos.end(), {x, y, z});
        vel.insert(vel.end(), {vx, vy, vz});
        rhop.push_back(rho);
        press.push_back(0.f);
        mass.push_back(m);
        type.push_back(std::uint8_t(t));
        excluded.push_back(excl);
        mk.push_back(mk_value);
    }

    /// The frame of part `index` at `time` (step `step`) over these arrays.
    io::PartFrame frame(int index, double time, long long step) const {
        io::PartFrame f;
        f.index = index;
        f.time = time;
        f.step = step;
        f.np = id.size();
        f.pos = pos.data();
        f.vel = vel.data();
        f.rhop = rhop.data();
        f.press = press.data();
        f.id = id.data();
        f.type = type.data();
        f.mk = mk.data();
        f.excluded = excluded.data();
        f.mass = mass.data();
        f.constants = constants;
        return f;
    }
};

}  // namespace seaspring::test
