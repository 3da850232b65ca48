// SeaSpring — MIT licence.
/// \file test_vcpm_bonds.cpp
/// \brief Tests of the VCPM bond network builder (counts by hand, symmetry, clamps, errors).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "gencase/vcpm_bonds.h"

using namespace seaspring;
using namespace seaspring::gencase;

namespace {

constexpr double kDp = 0.01;

/// Particles plus their lattice indices; pos = dp * lattice index. Callers add particles in
/// the file order (fixed, moving, solid, fluid).
struct Scene {
    ParticleSet ps;
    std::vector<Vec3i> lattice;

    void add(ParticleType t, std::uint16_t mk, int x, int y, int z) {
        const std::size_t k = ps.size();
        ps.resize(k + 1);
        ps.id[k] = static_cast<std::uint32_t>(k);
        ps.type[k] = t;
        ps.mk[k] = mk;
        ps.pos[k] = {kDp * x, kDp * y, kDp * z};
        lattice.push_back({x, y, z});
    }
    /// Block of nx*ny*nz particles starting at lattice (x0,y0,z0), x fastest.
    void block(ParticleType t, std::uint16_t mk, int x0, int y0, int z0, int nx, int ny, int nz) {
        for (int z = z0; z < z0 + nz; ++z)
            for (int y = y0; y < y0 + ny; ++y)
                for (int x = x0; x < x0 + nx; ++x) add(t, mk, x, y, z);
    }
    BondBuildInput input(bool two_d, std::map<std::uint16_t, std::vector<std::uint16_t>> clamps) const {
        BondBuildInput in;
        in.two_d = two_d;
        in.dp = kDp;
        in.lattice = &lattice;
        in.particles = &ps;
        in.clamp_mks = std::move(clamps);
        return in;
    }
};

std::size_t rowSize(const BondNetwork& net, std::size_t id) {
    const std::size_t r = id - net.first_solid;
    return net.offset[r + 1] - net.offset[r];
}

std::string messageOf(const BondBuildInput& in) {
    try {
        buildBondNetwork(in, nullptr);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

/// Every solid-solid slot i->j has a slot j->i with the same rest length and kind.
void expectSymmetric(const BondNetwork& net) {
    for (std::size_t r = 0; r < net.solidCount(); ++r) {
        const std::uint32_t i = net.first_solid + static_cast<std::uint32_t>(r);
        for (std::uint32_t s = net.offset[r]; s < net.offset[r + 1]; ++s) {
            if (net.kind[s] & BondClampFlag) continue;
            const std::uint32_t j = net.neighbour[s];
            ASSERT_GE(j, net.first_solid);
            const std::size_t rj = j - net.first_solid;
            ASSERT_LT(rj, net.solidCount());
            int found = 0;
            for (std::uint32_t t = net.offset[rj]; t < net.offset[rj + 1]; ++t)
                if (net.neighbour[t] == i) {
                    ++found;
                    EXPECT_EQ(net.rest_length[t], net.rest_length[s]);
                    EXPECT_EQ(net.kind[t], net.kind[s]);
                }
            EXPECT_EQ(found, 1) << "bond " << i << " -> " << j;
        }
    }
}

}  // namespace

TEST(VcpmBonds, LatticeOffsetsOrder) {
    const std::vector<Vec3i> expect3 = {
        {0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},             // first
        {0, -1, -1}, {-1, 0, -1}, {1, 0, -1}, {0, 1, -1},                                  // dz=-1
        {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0},                                    // dz=0
        {0, -1, 1}, {-1, 0, 1}, {1, 0, 1}, {0, 1, 1}};                                     // dz=+1
    const std::vector<Vec3i>& o3 = latticeOffsets(false);
    ASSERT_EQ(o3.size(), 18u);
    for (std::size_t k = 0; k < 18; ++k) {
        EXPECT_EQ(o3[k].x, expect3[k].x) << k;
        EXPECT_EQ(o3[k].y, expect3[k].y) << k;
        EXPECT_EQ(o3[k].z, expect3[k].z) << k;
    }
    const std::vector<Vec3i> expect2 = {{0, 0, -1}, {-1, 0, 0}, {1, 0, 0}, {0, 0, 1},
                                        {-1, 0, -1}, {1, 0, -1}, {-1, 0, 1}, {1, 0, 1}};
    const std::vector<Vec3i>& o2 = latticeOffsets(true);
    ASSERT_EQ(o2.size(), 8u);
    for (std::size_t k = 0; k < 8; ++k) {
        EXPECT_EQ(o2[k].x, expect2[k].x) << k;
        EXPECT_EQ(o2[k].y, 0) << k;
        EXPECT_EQ(o2[k].z, expect2[k].z) << k;
    }
    EXPECT_EQ(firstNeighbourCount(false), 6u);
    EXPECT_EQ(firstNeighbourCount(true), 4u);
}

TEST(VcpmBonds, Block3x3x3CountsByHand) {
    Scene sc;
    sc.add(ParticleType::Fixed, 1, 20, 20, 20);  // unrelated boundary particle before the solid
    sc.block(ParticleType::Solid, 5, 0, 0, 0, 3, 3, 3);
    sc.add(ParticleType::Fluid, 2, 3, 1, 1);     // fluid touching the block: no bond
    BondStats st;
    const BondNetwork net = buildBondNetwork(sc.input(false, {{5, {}}}), &st);

    // First-neighbour pairs: per direction 2 pairs per line * 9 lines = 18; 3 directions -> 54.
    // Second-neighbour pairs: per plane orientation, each of the 3 layers is a 3x3 grid with
    // 2*2 = 4 unit squares, 2 diagonals each -> 8 per layer, 24 per orientation; 3 -> 72.
    // Total pairs 54 + 72 = 126, slots 252. Per particle: centre 18, 6 face centres 5+8 = 13,
    // 12 edge centres 4+5 = 9, 8 corners 3+3 = 6: 18 + 78 + 108 + 48 = 252.
    EXPECT_EQ(st.solid_particles, 27u);
    EXPECT_EQ(st.bonds, 126u);
    EXPECT_EQ(st.clamp_bonds, 0u);
    EXPECT_EQ(st.surface_particles, 26u);
    EXPECT_EQ(st.isolated_particles, 0u);
    ASSERT_EQ(st.particles_per_mk.size(), 1u);
    EXPECT_EQ(st.particles_per_mk.at(5), 27u);

    EXPECT_EQ(net.first_solid, 1u);
    ASSERT_EQ(net.solidCount(), 27u);
    ASSERT_EQ(net.bondSlots(), 252u);
    EXPECT_EQ(net.rest_length.size(), 252u);
    EXPECT_EQ(net.kind.size(), 252u);
    auto idOf = [](int x, int y, int z) { return static_cast<std::size_t>(1 + x + 3 * y + 9 * z); };
    EXPECT_EQ(rowSize(net, idOf(1, 1, 1)), 18u);
    EXPECT_EQ(rowSize(net, idOf(1, 1, 0)), 13u);
    EXPECT_EQ(rowSize(net, idOf(1, 0, 0)), 9u);
    EXPECT_EQ(rowSize(net, idOf(2, 2, 2)), 6u);

    // Centre: slot s points at lattice(centre) + offset[s], in order.
    const std::size_t c = idOf(1, 1, 1) - net.first_solid;
    const std::vector<Vec3i>& off = latticeOffsets(false);
    for (std::size_t s = 0; s < 18; ++s) {
        const std::uint32_t j = net.neighbour[net.offset[c] + s];
        EXPECT_EQ(j, idOf(1 + off[s].x, 1 + off[s].y, 1 + off[s].z)) << s;
        EXPECT_EQ(net.kind[net.offset[c] + s], s < 6 ? BondFirst : BondSecond) << s;
    }
    // Corner (0,0,0): first +x, +y, +z; second (1,1,0), (1,0,1), (0,1,1) (offset order).
    const std::size_t r0 = idOf(0, 0, 0) - net.first_solid;
    const std::vector<std::size_t> corner = {idOf(1, 0, 0), idOf(0, 1, 0), idOf(0, 0, 1),
                                             idOf(1, 1, 0), idOf(1, 0, 1), idOf(0, 1, 1)};
    ASSERT_EQ(net.offset[r0 + 1] - net.offset[r0], 6u);
    for (std::size_t s = 0; s < 6; ++s) {
        EXPECT_EQ(net.neighbour[net.offset[r0] + s], corner[s]) << s;
        EXPECT_EQ(net.kind[net.offset[r0] + s], s < 3 ? BondFirst : BondSecond) << s;
    }

    // Rest lengths exact, and equal to the position distance.
    std::size_t n_first = 0, n_second = 0;
    for (std::size_t r = 0; r < 27; ++r)
        for (std::uint32_t s = net.offset[r]; s < net.offset[r + 1]; ++s) {
            if (net.kind[s] == BondFirst) {
                ++n_first;
                EXPECT_EQ(net.rest_length[s], kDp);
            } else {
                ++n_second;
                EXPECT_EQ(net.kind[s], BondSecond);
                EXPECT_EQ(net.rest_length[s], std::sqrt(2.0) * kDp);
            }
            const Vec3d d = sc.ps.pos[net.first_solid + r] - sc.ps.pos[net.neighbour[s]];
            EXPECT_NEAR(std::sqrt(dot(d, d)), net.rest_length[s], 1e-15);
        }
    EXPECT_EQ(n_first, 108u);
    EXPECT_EQ(n_second, 144u);
    expectSymmetric(net);
}

TEST(VcpmBonds, Square3x3In2D) {
    Scene sc;
    for (int z = 0; z < 3; ++z)
        for (int x = 0; x < 3; ++x) sc.add(ParticleType::Solid, 7, x, 0, z);
    BondStats st;
    const BondNetwork net = buildBondNetwork(sc.input(true, {{7, {}}}), &st);
    // First pairs: 2 per line * 3 lines * 2 directions = 12; second: 4 squares * 2 = 8.
    // Slots 40 = centre 8 + 4 edge centres (3+2) + 4 corners (2+1) = 8 + 20 + 12.
    EXPECT_EQ(st.solid_particles, 9u);
    EXPECT_EQ(st.bonds, 20u);
    EXPECT_EQ(st.surface_particles, 8u);
    ASSERT_EQ(net.bondSlots(), 40u);
    EXPECT_EQ(net.first_solid, 0u);
    EXPECT_EQ(rowSize(net, 4), 8u);  // centre (1,0,1)
    EXPECT_EQ(rowSize(net, 1), 5u);  // edge centre (1,0,0)
    EXPECT_EQ(rowSize(net, 0), 3u);  // corner
    // Centre row in offset order: (1,0,0) (0,0,1) (2,0,1) (1,0,2) then (0,0,0) (2,0,0) (0,0,2) (2,0,2).
    const std::vector<std::uint32_t> centre = {1, 3, 5, 7, 0, 2, 6, 8};
    for (std::size_t s = 0; s < 8; ++s) {
        EXPECT_EQ(net.neighbour[net.offset[4] + s], centre[s]) << s;
        EXPECT_EQ(net.rest_length[net.offset[4] + s], s < 4 ? kDp : std::sqrt(2.0) * kDp) << s;
    }
    expectSymmetric(net);
}

TEST(VcpmBonds, ClampBondsToPlateBelow) {
    for (bool top_is_clamp : {false, true}) {
        Scene sc;
        sc.block(ParticleType::Fixed, 3, -1, -1, -1, 5, 5, 1);   // 25-particle plate at z=-1
        sc.block(ParticleType::Moving, 4, -1, -1, 3, 5, 5, 1);   // plate at z=3
        sc.block(ParticleType::Solid, 9, 0, 0, 0, 3, 3, 3);
        std::vector<std::uint16_t> clamps = {3};
        if (top_is_clamp) clamps.push_back(4);
        BondStats st;
        const BondNetwork net = buildBondNetwork(sc.input(false, {{9, clamps}}), &st);
        // Each of the 9 bottom particles bonds to the plate site below (1) and the 4 sites
        // (0,+-1,-1), (+-1,0,-1), all inside the 5x5 plate: 9 * 5 = 45 per clamped plate.
        const std::size_t per_plate = 45;
        const std::size_t plates = top_is_clamp ? 2 : 1;
        EXPECT_EQ(st.bonds, 126u);
        EXPECT_EQ(st.clamp_bonds, plates * per_plate);
        // The bottom (and top) centre now has 13 + 5 = 18 bonds: no longer a surface particle.
        EXPECT_EQ(st.surface_particles, 26u - plates);
        EXPECT_EQ(net.first_solid, 50u);
        ASSERT_EQ(net.solidCount(), 27u);  // rows only for solids: clamp side stores nothing
        EXPECT_EQ(net.bondSlots(), 252u + plates * per_plate);
        // Bottom corner (0,0,0): 6 solid + 1 + 4 clamp; its clamp slots come first (dz=-1).
        ASSERT_EQ(net.offset[1] - net.offset[0], 11u);
        EXPECT_EQ(net.neighbour[0], 6u);  // plate (0,0,-1): id (x+1) + 5*(y+1) = 1 + 5
        EXPECT_EQ(net.kind[0], BondFirst | BondClampFlag);
        EXPECT_EQ(net.rest_length[0], kDp);
        std::size_t clamp_slots = 0;
        for (std::size_t s = 0; s < net.bondSlots(); ++s) {
            if (!(net.kind[s] & BondClampFlag)) continue;
            ++clamp_slots;
            EXPECT_LT(net.neighbour[s], 50u);
            if (!top_is_clamp) {
                EXPECT_LT(net.neighbour[s], 25u);
            }
            const std::uint8_t base = net.kind[s] & ~BondClampFlag;
            EXPECT_EQ(net.rest_length[s], base == BondFirst ? kDp : std::sqrt(2.0) * kDp);
        }
        EXPECT_EQ(clamp_slots, plates * per_plate);
        expectSymmetric(net);
    }
}

TEST(VcpmBonds, TouchingSolidsOfDifferentMkDoNotBond) {
    // Two 2x2x2 cubes side by side along x. Each cube: first 3*(1*2*2) = 12 pairs, second
    // 3 orientations * 2 layers * 1 square * 2 diagonals = 12 -> 24 pairs; two cubes 48.
    Scene two;
    two.block(ParticleType::Solid, 10, 0, 0, 0, 2, 2, 2);
    two.block(ParticleType::Solid, 11, 2, 0, 0, 2, 2, 2);
    BondStats st;
    const BondNetwork net = buildBondNetwork(two.input(false, {{10, {}}, {11, {}}}), &st);
    EXPECT_EQ(st.bonds, 48u);
    EXPECT_EQ(st.particles_per_mk.at(10), 8u);
    EXPECT_EQ(st.particles_per_mk.at(11), 8u);
    for (std::size_t r = 0; r < 16; ++r)
        for (std::uint32_t s = net.offset[r]; s < net.offset[r + 1]; ++s)
            EXPECT_EQ(two.ps.mk[net.neighbour[s]], two.ps.mk[r]);
    expectSymmetric(net);

    // Same geometry as one MK (4x2x2): first x 3*4 + y 4*2 + z 4*2 = 28, second
    // xy 2*3*2 + xz 2*3*2 + yz 4*1*2 = 32 -> 60 = 48 + 12 across the 2x2 interface
    // (4 first + each of the 4 interface particles has 2 in-plane partners on the other side).
    Scene one;
    one.block(ParticleType::Solid, 10, 0, 0, 0, 2, 2, 2);
    one.block(ParticleType::Solid, 10, 2, 0, 0, 2, 2, 2);
    BondStats st1;
    buildBondNetwork(one.input(false, {{10, {}}}), &st1);
    EXPECT_EQ(st1.bonds, 60u);
}

TEST(VcpmBonds, IsolatedParticleThrows) {
    Scene sc;
    sc.block(ParticleType::Solid, 5, 0, 0, 0, 2, 2, 2);
    sc.add(ParticleType::Solid, 5, 5, 0, 0);   // id 8, two sites away from the cube
    sc.add(ParticleType::Fluid, 1, 6, 0, 0);   // fluid next to it gives no bond
    const BondBuildInput in = sc.input(false, {{5, {}}});
    EXPECT_THROW(buildBondNetwork(in, nullptr), Error);
    const std::string msg = messageOf(in);
    EXPECT_NE(msg.find("1 solid particle(s) have no bond"), std::string::npos) << msg;
    EXPECT_NE(msg.find("id 8 "), std::string::npos) << msg;
    EXPECT_NE(msg.find("(0.05, 0, 0)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("a VCPM solid needs lattice neighbours at dp spacing"), std::string::npos) << msg;
    BondStats st;
    EXPECT_THROW(buildBondNetwork(in, &st), Error);
    EXPECT_EQ(st.isolated_particles, 1u);
    EXPECT_EQ(st.solid_particles, 9u);
}

TEST(VcpmBonds, InputErrors) {
    Scene sc;
    sc.add(ParticleType::Fixed, 3, 0, 0, -1);
    sc.add(ParticleType::Fluid, 2, 5, 5, 5);
    sc.block(ParticleType::Solid, 5, 0, 0, 0, 2, 1, 1);
    // Solid MK without particles.
    std::string msg = messageOf(sc.input(false, {{5, {}}, {99, {}}}));
    EXPECT_NE(msg.find("solid mk 99 has no particles"), std::string::npos) << msg;
    // Solid particle whose MK is not declared.
    msg = messageOf(sc.input(false, {}));
    EXPECT_NE(msg.find("mk 5) at (0, 0, 0)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("not declared as a VCPM solid"), std::string::npos) << msg;
    // Clamp MK that is fluid, or missing.
    msg = messageOf(sc.input(false, {{5, {2}}}));
    EXPECT_NE(msg.find("clamp mk 2 of solid mk 5 is a fluid mk"), std::string::npos) << msg;
    msg = messageOf(sc.input(false, {{5, {42}}}));
    EXPECT_NE(msg.find("clamp mk 42 of solid mk 5 has no particles"), std::string::npos) << msg;
    // With the plate particle (0,0,-1) as clamp: (0,0,0) bonds to it as first neighbour and
    // (1,0,0) as second neighbour -> 2 clamp bonds, plus the 1 solid pair.
    BondStats st;
    buildBondNetwork(sc.input(false, {{5, {3}}}), &st);
    EXPECT_EQ(st.clamp_bonds, 2u);
    EXPECT_EQ(st.bonds, 1u);
    // Two particles on one lattice site.
    sc.add(ParticleType::Solid, 5, 1, 0, 0);
    msg = messageOf(sc.input(false, {{5, {}}}));
    EXPECT_NE(msg.find("id 3 (solid, mk 5)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("id 4 (solid, mk 5)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("share one lattice site"), std::string::npos) << msg;
}

TEST(VcpmBonds, MatchesBruteForceAcrossBrickAndSignBoundaries) {
    // An irregular 2-MK body around a negative, far-off origin (the site lookup works in
    // 4x4x4 bricks; this crosses brick and sign boundaries), with a clamp plate and a
    // non-clamp wall. The reference rows come from an O(n^2) search.
    const int ox = -1000003, oy = 7, oz = -2;
    Scene sc;
    sc.block(ParticleType::Fixed, 3, ox - 6, oy - 6, oz - 5, 13, 13, 1);  // clamp plate
    sc.block(ParticleType::Fixed, 4, ox + 5, oy - 6, oz - 4, 1, 13, 10);  // wall, not a clamp
    for (std::uint16_t mk : {8, 9})
        for (int z = -5; z <= 5; ++z)
            for (int y = -5; y <= 5; ++y)
                for (int x = -5; x <= 5; ++x) {
                    if (x * x + y * y + z * z > 25 || z == -5 || x == 5 || (x * 7 + y * 3 + z) % 5 == 0)
                        continue;
                    if ((mk == 8) != (z < 0 || (z == 0 && x < 0))) continue;
                    sc.add(ParticleType::Solid, mk, ox + x, oy + y, oz + z);
                }
    const BondBuildInput in = sc.input(false, {{8, {3}}, {9, {}}});
    BondStats st;
    BondNetwork net;
    try {
        net = buildBondNetwork(in, &st);
    } catch (const Error&) {
        // Holes may leave isolated particles: then the reference must agree on that count.
    }
    const std::vector<Vec3i>& off = latticeOffsets(false);
    std::vector<std::uint32_t> ref_offset = {0}, ref_neighbour;
    std::vector<std::uint8_t> ref_kind;
    std::size_t isolated = 0;
    const std::size_t first = 169 + 130;  // plate 13*13, wall 13*10
    for (std::size_t i = first; i < sc.ps.size(); ++i) {
        const std::size_t before = ref_neighbour.size();
        for (std::size_t s = 0; s < off.size(); ++s) {
            const Vec3i t = sc.lattice[i] + off[s];
            for (std::size_t j = 0; j < sc.ps.size(); ++j) {
                const Vec3i l = sc.lattice[j];
                if (l.x != t.x || l.y != t.y || l.z != t.z) continue;
                const bool same_solid = sc.ps.type[j] == ParticleType::Solid && sc.ps.mk[j] == sc.ps.mk[i];
                const bool clamp = sc.ps.mk[i] == 8 && sc.ps.mk[j] == 3;
                if (!same_solid && !clamp) continue;
                ref_neighbour.push_back(static_cast<std::uint32_t>(j));
                ref_kind.push_back(static_cast<std::uint8_t>((s < 6 ? BondFirst : BondSecond) |
                                                             (clamp ? BondClampFlag : 0)));
            }
        }
        if (ref_neighbour.size() == before) ++isolated;
        ref_offset.push_back(static_cast<std::uint32_t>(ref_neighbour.size()));
    }
    EXPECT_EQ(st.isolated_particles, isolated);
    ASSERT_EQ(isolated, 0u) << "test geometry should have no isolated particle";
    EXPECT_EQ(st.solid_particles, sc.ps.size() - first);
    EXPECT_GT(st.clamp_bonds, 0u);
    std::size_t wall_neighbours = 0;  // solid particles next to the non-clamp wall
    for (std::size_t i = first; i < sc.ps.size(); ++i) wall_neighbours += sc.lattice[i].x == ox + 4;
    EXPECT_GT(wall_neighbours, 0u);
    EXPECT_EQ(net.first_solid, first);
    EXPECT_EQ(net.offset, ref_offset);
    EXPECT_EQ(net.neighbour, ref_neighbour);
    EXPECT_EQ(net.kind, ref_kind);
    expectSymmetric(net);
}

TEST(VcpmBonds, Deterministic) {
    Scene sc;
    sc.block(ParticleType::Fixed, 3, -1, -1, -1, 6, 5, 1);
    sc.block(ParticleType::Solid, 8, 0, 0, 0, 4, 3, 5);
    sc.block(ParticleType::Solid, 9, 0, 0, 5, 4, 3, 2);
    const BondBuildInput in = sc.input(false, {{8, {3}}, {9, {}}});
    const BondNetwork a = buildBondNetwork(in, nullptr);
    const BondNetwork b = buildBondNetwork(in, nullptr);
    EXPECT_EQ(a.first_solid, b.first_solid);
    EXPECT_EQ(a.offset, b.offset);
    EXPECT_EQ(a.neighbour, b.neighbour);
    EXPECT_EQ(a.rest_length, b.rest_length);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_GT(a.bondSlots(), 0u);
    expectSymmetric(a);
}
