// SeaSpring — MIT licence.
/// \file test_post_flow.cpp
/// \brief `seaspring-post flow` on hand-made part files: a block of water moving at a uniform
///        velocity through a plane (hand-computable counts, volume flow U A, mass flow rho U A),
///        the section limits, the sign of the normal, boundary and excluded particles ignored,
///        physics::sectionCrossing on its own, and the errors (option and file named).
///
/// Broken on purpose (both in one build, then restored), to see these tests fail:
///  - physics::sectionCrossing returned +1 for both directions (`dir = d0 < 0 && d1 >= 0 ? 1 :
///    d0 >= 0 && d1 < 0 ? 1 : 0`): ReversedNormalCountsNegative and SectionCrossingAlone failed;
///  - flowBetween used the earlier part's density for the volume (a.rhop): UniformFlowThroughPlane
///    failed on the volume and volume flow (the later part's density is 1250 there; no crossing
///    against the normal there, so the first break does not touch it).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "../unit/error_expect.h"
#include "core/particle_set.h"
#include "io/part_output.h"
#include "part_particles.h"
#include "physics/gauges.h"
#include "post/flow.h"
#include "post/part_series.h"
#include "test_files.h"

using namespace seaspring;

namespace {

std::string scratch(const std::string& tag) {
    const std::string d = testing::TempDir() + "/seaspring_" + tag + "_" + std::to_string(::getpid());
    std::filesystem::remove_all(d);
    return d;
}

/// A block of fluid on a lattice of spacing dp = 0.1 m: x = 0, 0.1, ..., 0.9; y = 0 .. 0.4 (5);
/// z = 0 .. 0.2 (3): 150 particles of 1 kg (rho 1000, dp^3 = 0.001 m^3), moving at U = 0.5 m/s
/// along x; part k at t = 0.2 k s, so each part is shifted by exactly one dp. Plus two boundary
/// particles that move too (they must not count) and, from part 2 on, one excluded fluid
/// particle that would otherwise cross. Returns OUTDIR.
std::string writeUniformFlow(const std::string& tag, int nparts, float rhop_later = 1000.f) {
    const std::string out = scratch(tag);
    const double dp = 0.1, U = 0.5, dt = 0.2;
    for (int k = 0; k < nparts; ++k) {
        test::PartParticles p;
        auto add = [&](double x, double y, double z, ParticleType t, std::uint8_t ex) {
            p.add(x, y, z, float(U), 0.f, 0.f, k == 0 ? 1000.f : rhop_later, 1.f, t, t == ParticleType::Fluid ? 1 : 11, ex);
        };
        for (int b = 0; b < 2; ++b) add(0.45 + U * dt * k, 0.1 * b, -0.1, ParticleType::Fixed, 0);
        for (int z = 0; z < 3; ++z)
            for (int y = 0; y < 5; ++y)
                for (int x = 0; x < 10; ++x) add(x * dp + U * dt * k, y * dp, z * dp, ParticleType::Fluid, 0);
        add(0.35 + U * dt * k, 0.2, 0.1, ParticleType::Fluid, k >= 2 ? 1 : 0);
        p.constants = {0.17, dp, "Wendland C2", 1000.0, 3, 1e5};
        io::writePartH5(out, p.frame(k, dt * k, 0));
    }
    return out;
}

}  // namespace

/// The plane x = 0.55: between two parts exactly one lattice column (5 x 3 = 15 particles,
/// 15 kg, 0.015 m^3) crosses it, so the volume flow is 0.075 m^3/s = U A (A = 0.5 x 0.3 m^2) and
/// the mass flow 75 kg/s = rho U A. The extra fluid particle at x = 0.35 + 0.1 k crosses between
/// parts 1 and 2 but is excluded in part 2: not counted. From part 1 on the density is 1250:
/// volumes are m / rho of the later part (0.0008 m^3 each).
TEST(PostFlow, UniformFlowThroughPlane) {
    const std::string out = writeUniformFlow("post_flow_uniform", 5, 1250.f);
    post::FlowOptions o;
    o.dirin = out;
    o.plane = {0.55, 0, 0, 1, 0, 0};
    o.savecsv = out + "/flow.csv";
    std::ostringstream log;
    EXPECT_EQ(post::runFlow(o, log), 4);
    std::string h;
    const auto r = test::readCsv(o.savecsv, h);
    EXPECT_EQ(h, "part;time;npos;nneg;mass;volume;massflow;volumeflow;masstotal;volumetotal");
    ASSERT_EQ(r.size(), 4u);
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(r[k][0], std::to_string(k + 1));
        EXPECT_NEAR(std::stod(r[k][1]), 0.2 * (k + 1), 1e-12);
        EXPECT_EQ(r[k][2], "15") << "part " << k + 1;
        EXPECT_EQ(r[k][3], "0");
        EXPECT_NEAR(std::stod(r[k][4]), 15.0, 1e-9);
        EXPECT_NEAR(std::stod(r[k][5]), 15 * 1.0 / 1250.0, 1e-12);
        EXPECT_NEAR(std::stod(r[k][6]), 75.0, 1e-7);                      // rho U A with rho = m/dp^3
        EXPECT_NEAR(std::stod(r[k][7]), 0.075 * 1000.0 / 1250.0, 1e-9);  // U A, compressed 1000/1250
        EXPECT_NEAR(std::stod(r[k][8]), 15.0 * (k + 1), 1e-9);
    }
    // Limits: only y <= 0.25 (3 of the 5 rows): 9 particles per part.
    o.limits = {-1, -1, -1, 2, 0.25, 1};
    const physics::PlaneSection s = post::makeSection(o.plane, o.limits);
    const io::PartData a = io::readPartH5(out + "/data/part_0000.h5"), b = io::readPartH5(out + "/data/part_0001.h5");
    const post::FlowCount c = post::flowBetween(s, a, b, "b");
    EXPECT_EQ(c.npos, 9);
    EXPECT_NEAR(c.mass, 9.0, 1e-12);
}

TEST(PostFlow, ReversedNormalCountsNegative) {
    const std::string out = writeUniformFlow("post_flow_reversed", 2);
    const physics::PlaneSection s = post::makeSection({0.55, 0, 0, -2, 0, 0}, {});  // normalised
    EXPECT_DOUBLE_EQ(s.n.x, -1.0);
    const io::PartData a = io::readPartH5(out + "/data/part_0000.h5"), b = io::readPartH5(out + "/data/part_0001.h5");
    const post::FlowCount c = post::flowBetween(s, a, b, "b");
    EXPECT_EQ(c.npos, 0);
    EXPECT_EQ(c.nneg, 15);
    EXPECT_NEAR(c.mass, -15.0, 1e-12);
    EXPECT_NEAR(c.volume, -0.015, 1e-12);
    // Backwards in time (b -> a): the other direction.
    const post::FlowCount back = post::flowBetween(s, b, a, "a");
    EXPECT_EQ(back.npos, 15);
}

TEST(PostFlow, SectionCrossingAlone) {
    const double inf = 1e300;
    const physics::PlaneSection s{{0, 0, 0}, {0, 0, 1}, {-1, -1, -inf}, {1, 1, inf}};
    using physics::Double3;
    EXPECT_EQ(physics::sectionCrossing(s, Double3{0, 0, -0.1}, Double3{0, 0, 0.1}), 1);
    EXPECT_EQ(physics::sectionCrossing(s, Double3{0, 0, 0.1}, Double3{0, 0, -0.1}), -1);
    EXPECT_EQ(physics::sectionCrossing(s, Double3{0, 0, -0.1}, Double3{0, 0, 0.0}), 1);  // stops on the plane
    EXPECT_EQ(physics::sectionCrossing(s, Double3{0, 0, 0.1}, Double3{0, 0, 0.2}), 0);
    // Crossing point (1.5, 0, 0): outside the section although both ends are above/below it.
    EXPECT_EQ(physics::sectionCrossing(s, Double3{1, 0, -0.1}, Double3{2, 0, 0.1}), 0);
    EXPECT_EQ(physics::sectionCrossing(s, Double3{0.5, 0, -0.1}, Double3{1.3, 0, 0.3}), 1);  // at x = 0.7
}

TEST(PostFlow, Errors) {
    EXPECT_HAS(test::errorOf([] { post::makeSection({0, 0, 0, 1, 0}, {}); }), "-plane: expected 6 numbers");
    EXPECT_HAS(test::errorOf([] { post::makeSection({0, 0, 0, 0, 0, 0}, {}); }), "is zero");
    EXPECT_HAS(test::errorOf([] { post::makeSection({0, 0, 0, 1, 0, 0}, {0, 0, 0, 1, -1, 1}); }), "-limits: ymin 0");
    const std::string out = writeUniformFlow("post_flow_errors", 1);
    post::FlowOptions o;
    o.dirin = out;
    o.plane = {0.55, 0, 0, 1, 0, 0};
    o.savecsv = out + "/flow.csv";
    std::ostringstream log;
    EXPECT_HAS(test::errorOf([&] { post::runFlow(o, log); }), "at least two part files");
    EXPECT_FALSE(std::ifstream(o.savecsv).good());
    o.dirin = out + "/nowhere";
    EXPECT_HAS(test::errorOf([&] { post::runFlow(o, log); }), out + "/nowhere/data: no such folder");
}
