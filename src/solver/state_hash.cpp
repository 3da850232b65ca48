// SeaSpring — MIT licence.
/// \file state_hash.cpp
#include "solver/state_hash.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.h"

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
    // The fields flagged kHashed in the field table (physics/particle_fields.h), in table
    // order, particle after particle (id order).
    std::vector<std::pair<const unsigned char*, std::size_t>> fields;  // (bytes, bytes per particle)
    std::size_t np = s.pos.size();
    s.forEachField([&](const auto& v, unsigned flags) {
        if ((flags & physics::kHashed) == 0) return;
        using T = typename std::decay_t<decltype(v)>::value_type;
        if (v.size() != np) throw Error("stateHash: a hashed field has " + std::to_string(v.size()) +
                                        " values for " + std::to_string(np) + " particles");
        fields.emplace_back(reinterpret_cast<const unsigned char*>(v.data()), sizeof(T));
    });
    for (std::size_t i = 0; i < np; ++i)
        for (const auto& f : fields) mix(h, f.first + i * f.second, f.second);
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
