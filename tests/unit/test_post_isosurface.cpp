// SeaSpring — MIT licence.
/// \file test_post_isosurface.cpp
/// \brief `seaspring-post isosurface`, the grid step (the contouring runs under pvpython:
///        tests/python/test_isosurface.py): on a hand-made block of still water the grid's mass
///        field is the particle mass inside, 0 beyond the kernel's reach, and crosses the default
///        level (0.5 m in 3D) half a particle spacing above the top particles; the .vti file;
///        the errors (no pvpython, bad options).
///
/// Broken on purpose once (then restored), to see this test fail: isosurfaceLevel returned
/// swlMassLimitCoef(dim) without the factor massfluid: DefaultLevelAndSurfaceHeight failed (the
/// level 0.5 kg lies above every node, no crossing found).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
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
#include "post/isosurface.h"

using namespace seaspring;

namespace {

const double kDp = 0.02, kH = 0.0346, kTop = 0.1;  // h = sqrt(3) dp, top particle row at z = 0.1

std::string scratch(const std::string& tag) {
    const std::string d = testing::TempDir() + "/seaspring_" + tag + "_" + std::to_string(::getpid());
    std::filesystem::remove_all(d);
    return d;
}

/// Still water on a lattice: x 0 .. 0.3, y 0 .. 0.2, z 0 .. 0.1 (16 x 11 x 6 particles),
/// rho 1000, m = rho dp^3 = 8e-3 kg, Wendland C2, 3D, no walls. One part file: OUTDIR.
std::string writeBlock(const std::string& tag) {
    const std::string out = scratch(tag);
    test::PartParticles p;
    for (int z = 0; z <= 5; ++z)
        for (int y = 0; y <= 10; ++y)
            for (int x = 0; x <= 15; ++x)
                p.add(x * kDp, y * kDp, z * kDp, 0.f, 0.f, 0.f, 1000.f, float(1000 * kDp * kDp * kDp), ParticleType::Fluid, 1);
    p.constants = {kH, kDp, "Wendland C2", 1000.0, 3, 1.6e5};
    io::writePartH5(out, p.frame(0, 0.0, 0));
    return out;
}

std::string readText(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

}  // namespace

TEST(PostIsosurface, DefaultLevelAndSurfaceHeight) {
    const std::string out = writeBlock("post_iso_block");
    const io::PartData d = io::readPartH5(out + "/data/part_0000.h5");
    post::IsosurfaceOptions o;
    const post::IsoGrid g = post::isosurfaceGrid(d, o, "block");
    const double m = 1000 * kDp * kDp * kDp;
    EXPECT_NEAR(g.massfluid, m, 1e-9);
    const double level = post::isosurfaceLevel(o, g.massfluid, g.dim);
    EXPECT_NEAR(level, 0.5 * m, 1e-9);  // m is a float in the part file
    // Grid: the fluid's box grown by 2h + dp on each side, nodes dp apart.
    EXPECT_NEAR(g.grid.origin[2], -(2 * kH + kDp), 1e-12);
    EXPECT_EQ(g.grid.spacing[0], kDp);
    ASSERT_EQ(g.arrays.size(), 2u);
    const std::vector<float>& mass = g.arrays[0].values;
    const std::vector<float>& wsum = g.arrays[1].values;
    auto at = [&](int x, int y, int z) { return std::size_t(x + g.grid.dims[0] * (y + g.grid.dims[1] * z)); };
    const int cx = g.grid.dims[0] / 2, cy = g.grid.dims[1] / 2;
    // Column through the middle: inside ~m (wsum ~1), far above 0; the level is crossed between
    // nodes, linearly interpolated (as marching cubes does).
    double zcross = -1;
    for (int z = 1; z < g.grid.dims[2]; ++z) {
        const double a = mass[at(cx, cy, z - 1)], b = mass[at(cx, cy, z)];
        if (a >= level && b < level) zcross = g.grid.origin[2] + kDp * (z - 1 + (a - level) / (a - b));
    }
    const std::size_t mid = at(cx, cy, int(std::lround((0.05 - g.grid.origin[2]) / kDp)));
    std::printf("[ isosurface ] mass in the middle %.6g (m = %.6g), wsum %.6g; level crossed at z = %.5g (top row %.3g)\n",
                mass[mid], m, wsum[mid], zcross, kTop);
    EXPECT_NEAR(mass[mid], m, 0.02 * m);
    EXPECT_NEAR(wsum[mid], 1.0, 0.02);
    EXPECT_EQ(mass[at(cx, cy, g.grid.dims[2] - 1)], 0.f);
    EXPECT_EQ(mass[at(0, 0, 0)], 0.f);
    // The SWL gauge's convention puts the surface about half a spacing above the top particles.
    EXPECT_NEAR(zcross, kTop + 0.5 * kDp, 0.5 * kDp);

    // The .vti file: header and size.
    io::writeImageVti(out + "/g.vti", g.grid, g.arrays);
    const std::string text = readText(out + "/g.vti");
    EXPECT_HAS(text, "<VTKFile type=\"ImageData\"");
    EXPECT_HAS(text, "Name=\"mass\"");
    EXPECT_HAS(text, "Name=\"wsum\"");
    EXPECT_GT(text.size(), 2 * g.grid.nodes() * sizeof(float));
}

TEST(PostIsosurface, GridOnlyAndErrors) {
    const std::string out = writeBlock("post_iso_errors");
    post::IsosurfaceOptions o;
    o.dirin = out;
    o.savevtk = out + "/surf/Surface";
    o.gridonly = true;
    o.var = "wsum";
    std::ostringstream log;
    EXPECT_EQ(post::runIsosurface(o, log), 1);
    EXPECT_TRUE(std::ifstream(out + "/surf/Surface_0000.vti").good());
    EXPECT_FALSE(std::ifstream(out + "/surf/Surface_0000.vtp").good());
    EXPECT_HAS(readText(out + "/surf/Surface_isosurface.txt"), "0.5\t" + out + "/surf/Surface_0000.vti\t");
    // No pvpython anywhere: a clear error before any work.
    o.gridonly = false;
    o.savevtk = out + "/surf2/Surface";
    const char* path = std::getenv("PATH");
    const std::string saved_path = path ? path : "";
    const char* pv = std::getenv("SEASPRING_PVPYTHON");
    const std::string saved_pv = pv ? pv : "";
    ::setenv("PATH", "/nonexistent", 1);
    ::unsetenv("SEASPRING_PVPYTHON");
    const std::string e = test::errorOf([&] { post::runIsosurface(o, log); });
    ::setenv("PATH", saved_path.c_str(), 1);
    if (!saved_pv.empty()) ::setenv("SEASPRING_PVPYTHON", saved_pv.c_str(), 1);
    EXPECT_HAS(e, "pvpython (ParaView) not found");
    EXPECT_HAS(e, "-gridonly");
    EXPECT_FALSE(std::filesystem::exists(out + "/surf2"));
    o.var = "press";
    EXPECT_HAS(test::errorOf([&] { post::runIsosurface(o, log); }), "-var: 'press'");
    o.var = "mass";
    o.limits = {0, 0, 0, 1, 1};
    EXPECT_HAS(test::errorOf([&] { post::runIsosurface(o, log); }), "-limits: expected 6 numbers");
    o.limits.clear();
    o.gridonly = true;
    o.distnode = 1e-5;  // 3e4 x 2e4 x 1.5e4 nodes
    EXPECT_HAS(test::errorOf([&] { post::runIsosurface(o, log); }), "more than 2^28");
}
