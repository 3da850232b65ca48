// SeaSpring — MIT licence.
/// \file particle_set.cpp
#include "core/particle_set.h"

namespace seaspring {

const char* particleTypeName(ParticleType t) {
    switch (t) {
        case ParticleType::Fixed: return "fixed";
        case ParticleType::Moving: return "moving";
        case ParticleType::Solid: return "solid";
        case ParticleType::Fluid: return "fluid";
    }
    return "unknown";
}

std::size_t ParticleSet::boundaryCount() const {
    std::size_t n = 0;
    for (ParticleType t : type) n += (t != ParticleType::Fluid) ? 1 : 0;
    return n;
}

void ParticleSet::reserve(std::size_t n) {
    id.reserve(n); type.reserve(n); mk.reserve(n); pos.reserve(n);
    vel.reserve(n); rhop.reserve(n); mass.reserve(n);
}

void ParticleSet::resize(std::size_t n) {
    id.resize(n); type.resize(n); mk.resize(n); pos.resize(n);
    vel.resize(n); rhop.resize(n); mass.resize(n);
}

}  // namespace seaspring
