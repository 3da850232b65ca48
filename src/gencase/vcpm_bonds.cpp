// SeaSpring — MIT licence.
/// \file vcpm_bonds.cpp
/// \brief VCPM bond network construction: lattice-site lookup and CSR assembly.
#include "gencase/vcpm_bonds.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace seaspring::gencase {

namespace {

/// Offsets with |d|^2 == 1 then |d|^2 == 2, each in lexicographic (dz, dy, dx) order.
std::vector<Vec3i> makeOffsets(bool two_d) {
    std::vector<Vec3i> out;
    for (int norm2 = 1; norm2 <= 2; ++norm2)
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if (two_d && dy != 0) continue;
                    if (dx * dx + dy * dy + dz * dz == norm2) out.push_back({dx, dy, dz});
                }
    return out;
}

std::uint64_t hashSite(const Vec3i& v) {
    // splitmix64 finaliser over the three components (brick coordinates here).
    std::uint64_t h = static_cast<std::uint32_t>(v.x);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(v.y);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(v.z);
    h ^= h >> 30; h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27; h *= 0x94D049BB133111EBull;
    h ^= h >> 31;
    return h;
}

/// Map lattice site -> particle id, stored as 4x4x4 bricks of ids found through a small
/// open-addressing (linear probing) table of brick coordinates. Neighbouring sites share a
/// brick, so the lookups stay in cache (a flat hash over millions of sites is memory bound).
class SiteTable {
public:
    static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;

    /// Inserts site -> id; returns kEmpty, or the id already stored at that site.
    std::uint32_t insert(const Vec3i& site, std::uint32_t id) {
        const Vec3i key = brickOf(site);
        std::uint32_t brick = findBrick(key);
        if (brick == kEmpty) brick = addBrick(key);
        std::uint32_t& slot = ids_[std::size_t(brick) * kBrickSites + localIndex(site, key)];
        if (slot != kEmpty) return slot;
        slot = id;
        return kEmpty;
    }
    /// Id at `site`, or kEmpty.
    std::uint32_t find(const Vec3i& site) const {
        const Vec3i key = brickOf(site);
        const std::uint32_t brick = findBrick(key);
        if (brick == kEmpty) return kEmpty;
        return ids_[std::size_t(brick) * kBrickSites + localIndex(site, key)];
    }

private:
    static constexpr int kSide = 4;
    static constexpr std::size_t kBrickSites = kSide * kSide * kSide;
    struct Entry {
        Vec3i key;
        std::uint32_t brick;
    };

    static int floorDiv(int v) { return (v >= 0 ? v : v - (kSide - 1)) / kSide; }
    static Vec3i brickOf(const Vec3i& s) { return {floorDiv(s.x), floorDiv(s.y), floorDiv(s.z)}; }
    static std::size_t localIndex(const Vec3i& s, const Vec3i& key) {
        return std::size_t(s.x - kSide * key.x) +
               kSide * (std::size_t(s.y - kSide * key.y) + kSide * std::size_t(s.z - kSide * key.z));
    }
    static bool same(const Vec3i& a, const Vec3i& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

    std::uint32_t findBrick(const Vec3i& key) const {
        if (table_.empty()) return kEmpty;
        for (std::size_t h = hashSite(key) & mask_;; h = (h + 1) & mask_) {
            const Entry& e = table_[h];
            if (e.brick == kEmpty || same(e.key, key)) return e.brick;
        }
    }
    std::uint32_t addBrick(const Vec3i& key) {
        const std::uint32_t brick = static_cast<std::uint32_t>(ids_.size() / kBrickSites);
        if (2 * (std::size_t(brick) + 1) > table_.size()) rehash(std::max<std::size_t>(64, 2 * table_.size()));
        place(key, brick);
        ids_.resize(ids_.size() + kBrickSites, kEmpty);
        return brick;
    }
    void place(const Vec3i& key, std::uint32_t brick) {
        std::size_t h = hashSite(key) & mask_;
        while (table_[h].brick != kEmpty) h = (h + 1) & mask_;
        table_[h] = Entry{key, brick};
    }
    void rehash(std::size_t capacity) {
        std::vector<Entry> old;
        old.swap(table_);
        table_.assign(capacity, Entry{{0, 0, 0}, kEmpty});
        mask_ = capacity - 1;
        for (const Entry& e : old)
            if (e.brick != kEmpty) place(e.key, e.brick);
    }

    std::vector<Entry> table_;       ///< brick coordinate -> brick number (capacity 2^k)
    std::size_t mask_ = 0;
    std::vector<std::uint32_t> ids_; ///< kBrickSites ids per brick, kEmpty where no particle
};

std::string describe(const ParticleSet& ps, const std::vector<Vec3i>& lattice, std::size_t k) {
    const Vec3d p = ps.pos[k];
    const Vec3i l = lattice[k];
    return detail::concat("id ", k, " (", particleTypeName(ps.type[k]), ", mk ", ps.mk[k],
                          ") at (", p.x, ", ", p.y, ", ", p.z, "), lattice (", l.x, ", ", l.y,
                          ", ", l.z, ")");
}

struct MkInfo {
    ParticleType type;
    std::size_t count = 0;
};

}  // namespace

const std::vector<Vec3i>& latticeOffsets(bool two_d) {
    static const std::vector<Vec3i> offsets_3d = makeOffsets(false);
    static const std::vector<Vec3i> offsets_2d = makeOffsets(true);
    return two_d ? offsets_2d : offsets_3d;
}

std::size_t firstNeighbourCount(bool two_d) { return two_d ? 4 : 6; }

BondNetwork buildBondNetwork(const BondBuildInput& in, BondStats* stats) {
    SEASPRING_CHECK(in.particles != nullptr && in.lattice != nullptr,
                    "buildBondNetwork: particles and lattice must be given");
    const ParticleSet& ps = *in.particles;
    const std::vector<Vec3i>& lattice = *in.lattice;
    const std::size_t n = ps.size();
    SEASPRING_CHECK(lattice.size() == n, "buildBondNetwork: ", lattice.size(),
                    " lattice indices for ", n, " particles (expected one per particle)");
    SEASPRING_CHECK(ps.type.size() == n && ps.mk.size() == n && ps.pos.size() == n,
                    "buildBondNetwork: particle arrays of different sizes");
    SEASPRING_CHECK(std::isfinite(in.dp) && in.dp > 0.0, "buildBondNetwork: dp=", in.dp,
                    " (expected a finite value > 0)");
    for (std::size_t k = 0; k < n; ++k)
        SEASPRING_CHECK(ps.id[k] == k, "buildBondNetwork: particle at index ", k, " has id ",
                        ps.id[k], " (expected ids equal to the index)");

    // Per-MK type and count; an MK must hold one particle type only.
    std::map<std::uint16_t, MkInfo> mk_info;
    for (std::size_t k = 0; k < n; ++k) {
        auto [it, inserted] = mk_info.try_emplace(ps.mk[k], MkInfo{ps.type[k], 0});
        if (!inserted && it->second.type != ps.type[k])
            throw Error(detail::concat("VCPM bonds: mk ", ps.mk[k], " holds both ",
                                       particleTypeName(it->second.type), " and ",
                                       particleTypeName(ps.type[k]), " particles (particle ",
                                       describe(ps, lattice, k), "); expected one type per mk"));
        ++it->second.count;
    }

    // Every declared solid MK has solid particles; every clamp MK has boundary particles.
    std::vector<bool> is_clamp_mk(65536, false);
    for (const auto& [solid_mk, clamps] : in.clamp_mks) {
        auto it = mk_info.find(solid_mk);
        if (it == mk_info.end() || it->second.type != ParticleType::Solid)
            throw Error(detail::concat(
                "VCPM bonds: solid mk ", solid_mk, " has no particles",
                (it == mk_info.end() ? std::string()
                                     : detail::concat(" (its ", it->second.count, " particles are ",
                                                      particleTypeName(it->second.type), ")")),
                "; expected a VCPM solid made of lattice particles"));
        for (std::uint16_t c : clamps) {
            auto ct = mk_info.find(c);
            if (ct == mk_info.end())
                throw Error(detail::concat("VCPM bonds: clamp mk ", c, " of solid mk ", solid_mk,
                                           " has no particles; expected a fixed or moving "
                                           "boundary mk"));
            if (ct->second.type != ParticleType::Fixed && ct->second.type != ParticleType::Moving)
                throw Error(detail::concat("VCPM bonds: clamp mk ", c, " of solid mk ", solid_mk,
                                           " is a ", particleTypeName(ct->second.type),
                                           " mk; expected a fixed or moving boundary mk"));
            is_clamp_mk[c] = true;
        }
    }

    // Solid particles: contiguous, each with a declared MK.
    std::size_t first = n, n_solid = 0;
    for (std::size_t k = 0; k < n; ++k) {
        if (ps.type[k] == ParticleType::Solid) {
            if (first == n) first = k;
            ++n_solid;
            if (in.clamp_mks.count(ps.mk[k]) == 0)
                throw Error(detail::concat("VCPM bonds: solid particle ", describe(ps, lattice, k),
                                           " has an mk that is not declared as a VCPM solid"));
        }
    }
    if (n_solid > 0)
        SEASPRING_CHECK(std::all_of(ps.type.begin() + first, ps.type.begin() + first + n_solid,
                                    [](ParticleType t) { return t == ParticleType::Solid; }),
                        "buildBondNetwork: solid particles are not contiguous (first at id ",
                        first, ", ", n_solid, " in all)");

    // Lattice site -> particle id, over solid and clamp particles only.
    SiteTable site;
    for (std::size_t k = 0; k < n; ++k) {
        if (ps.type[k] != ParticleType::Solid && !is_clamp_mk[ps.mk[k]]) continue;
        const std::uint32_t other = site.insert(lattice[k], static_cast<std::uint32_t>(k));
        if (other != SiteTable::kEmpty)
            throw Error(detail::concat("VCPM bonds: particles ", describe(ps, lattice, other),
                                       " and ", describe(ps, lattice, k),
                                       " share one lattice site; expected at most one solid or "
                                       "clamp particle per site"));
    }

    const std::vector<Vec3i>& offsets = latticeOffsets(in.two_d);
    SEASPRING_CHECK(n_solid * offsets.size() <= 0xFFFFFFFFull, "buildBondNetwork: ", n_solid,
                    " solid particles exceed the 32-bit bond index range");
    const std::size_t n_first = firstNeighbourCount(in.two_d);
    const double rest_first = in.dp;
    const double rest_second = std::sqrt(2.0) * in.dp;

    BondNetwork net;
    net.first_solid = static_cast<std::uint32_t>(n_solid > 0 ? first : 0);
    net.offset.reserve(n_solid + 1);
    net.offset.push_back(0);
    net.neighbour.reserve(n_solid * offsets.size());
    net.rest_length.reserve(n_solid * offsets.size());
    net.kind.reserve(n_solid * offsets.size());

    BondStats st;
    st.solid_particles = n_solid;
    std::size_t solid_slots = 0, first_isolated = n;
    const std::vector<std::uint16_t>* clamps = nullptr;
    std::uint16_t clamps_of = 0;
    for (std::size_t i = first; i < first + n_solid; ++i) {
        const std::uint16_t mk = ps.mk[i];
        if (clamps == nullptr || clamps_of != mk) {
            clamps = &in.clamp_mks.at(mk);
            clamps_of = mk;
        }
        ++st.particles_per_mk[mk];
        const std::size_t row_start = net.neighbour.size();
        for (std::size_t s = 0; s < offsets.size(); ++s) {
            const std::uint32_t j = site.find(lattice[i] + offsets[s]);
            if (j == SiteTable::kEmpty) continue;
            std::uint8_t kind = s < n_first ? BondFirst : BondSecond;
            if (ps.type[j] == ParticleType::Solid) {
                if (ps.mk[j] != mk) continue;
                ++solid_slots;
            } else {
                if (std::find(clamps->begin(), clamps->end(), ps.mk[j]) == clamps->end()) continue;
                kind |= BondClampFlag;
                ++st.clamp_bonds;
            }
            net.neighbour.push_back(j);
            net.rest_length.push_back(s < n_first ? rest_first : rest_second);
            net.kind.push_back(kind);
        }
        const std::size_t row_slots = net.neighbour.size() - row_start;
        if (row_slots < offsets.size()) ++st.surface_particles;
        if (row_slots == 0) {
            if (st.isolated_particles == 0) first_isolated = i;
            ++st.isolated_particles;
        }
        net.offset.push_back(static_cast<std::uint32_t>(net.neighbour.size()));
    }
    SEASPRING_CHECK(solid_slots % 2 == 0, "buildBondNetwork: odd number of solid-solid slots (",
                    solid_slots, ")");
    st.bonds = solid_slots / 2;
    if (stats != nullptr) *stats = st;

    if (st.isolated_particles > 0)
        throw Error(detail::concat("VCPM bonds: ", st.isolated_particles,
                                   " solid particle(s) have no bond at all; the first is ",
                                   describe(ps, lattice, first_isolated),
                                   "; a VCPM solid needs lattice neighbours at dp spacing (dp=",
                                   in.dp, ")"));
    return net;
}

}  // namespace seaspring::gencase
