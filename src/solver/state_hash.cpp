// SeaSpring — MIT licence.
/// \file state_hash.cpp
#include "solver/state_hash.h"

#include <cstdio>
#include <cstring>

namespace seaspring::solver {

namespace {
constexpr std::uint64_t kFnvOffset = 1469598103934665603ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

void mix(std::uint64_t& h, const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= kFnvPrime;
    }
}
}  // namespace

std::uint64_t stateHash(const HostState& s) {
    std::uint64_t h = kFnvOffset;
    for (std::size_t i = 0; i < s.pos.size(); ++i) {
        const double p[3] = {s.pos[i].x, s.pos[i].y, s.pos[i].z};
        const float v[4] = {s.velrho[i].x, s.velrho[i].y, s.velrho[i].z, s.velrho[i].w};
        mix(h, p, sizeof p);
        mix(h, v, sizeof v);
        mix(h, &s.excl[i], 1);
    }
    // VCPM solids (absent without solids, so fluid-only hashes are unchanged): the
    // double-precision velocities and every bond's state.
    for (const physics::Double3& v : s.solid_vel) {
        const double d[3] = {v.x, v.y, v.z};
        mix(h, d, sizeof d);
    }
    if (!s.bond_broken.empty()) mix(h, s.bond_broken.data(), s.bond_broken.size());
    return h;
}

std::string hashHex(std::uint64_t h) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

}  // namespace seaspring::solver
