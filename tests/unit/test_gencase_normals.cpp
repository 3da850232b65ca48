// SeaSpring — MIT licence.
/// \file test_gencase_normals.cpp
/// \brief mDBC normals in gencase: shape sets recorded by drawbox while drawshapes is on,
///        the ghost vectors of the boundary particles (2D tank, 3D obstacle, transforms,
///        SPHERIC Test 2), the HDF5 round trip of /particles/normal, and the errors.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "core/error.h"
#include "error_expect.h"
#include "gencase/boundary_normals.h"
#include "gencase_test_util.h"
#include "io/case_h5.h"
#include "io/h5_util.h"

using namespace seaspring;
using namespace seaspring::gencase;

namespace {

namespace fs = std::filesystem;

constexpr double kDp = 0.1;

const char* kNormals =
    "<normals active=\"true\"><distanceh value=\"2.0\"/>"
    "<geometryfile file=\"[CaseName]_hdp_Actual.vtk\"/></normals>";

/// 2D tank 0..2 x 0..1.5 (3 wall layers outwards, open top) with water 0.1..1.9 x 0.1..0.8,
/// and its interface: the same box with invert="true" shrunk by half a dp.
const char* kTank2D =
    "<setactive drawpoints=\"0\" drawshapes=\"1\"/>\n"
    "<setshapemode>actual | bound</setshapemode>\n"
    "<setmkbound mk=\"0\"/>\n"
    "<setnormalinvert invert=\"true\"/>\n"
    "<drawbox><boxfill>bottom|left|right</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
    "<size x=\"2\" y=\"0\" z=\"1.5\"/><layers vdp=\"-0.5\"/></drawbox>\n"
    "<shapeout file=\"hdp\"/>\n"
    "<resetdraw/>\n"
    "<setmkfluid mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0.1\" y=\"0\" z=\"0.1\"/>"
    "<size x=\"1.8\" y=\"0\" z=\"0.7\"/></drawbox>\n"
    "<setmkbound mk=\"0\"/><drawbox><boxfill>bottom|left|right</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
    "<size x=\"2\" y=\"0\" z=\"1.5\"/><layers vdp=\"0,1,2\"/></drawbox>\n";

/// Writes the case XML into a fresh scratch dir; returns the definition's path.
std::string writeCase(const std::string& tag, const std::string& mainlist, bool two_d,
                      const std::string& casedef_extra, std::string* xml_out = nullptr) {
    const std::string xml = test::caseXml(mainlist, kDp, two_d, casedef_extra);
    if (xml_out) *xml_out = xml;
    return test::writeFile(test::scratchDir(tag), "Case_Def.xml", xml);
}

/// Index of the particle at `x` (a test failure and npos when none).
std::size_t at(const ParticleSet& p, Vec3d x) {
    for (std::size_t i = 0; i < p.size(); ++i)
        if (std::fabs(p.pos[i].x - x.x) < 1e-9 && std::fabs(p.pos[i].y - x.y) < 1e-9 &&
            std::fabs(p.pos[i].z - x.z) < 1e-9)
            return i;
    ADD_FAILURE() << "no particle at (" << x.x << ", " << x.y << ", " << x.z << ")";
    return std::string::npos;
}

/// Expects the ghost vector of the particle at `x` to be `g` (in dp) within 1e-6 dp.
void expectGhost(const ParticleSet& p, Vec3d x, Vec3d g_dp, double dp = kDp) {
    const std::size_t i = at(p, x);
    if (i == std::string::npos) return;
    ASSERT_LT(i, p.normal.size()) << "particle " << i << " has no normal entry";
    const Vec3f n = p.normal[i];
    const std::string where =
        "at (" + std::to_string(x.x) + ", " + std::to_string(x.y) + ", " + std::to_string(x.z) + ")";
    EXPECT_NEAR(n.x, g_dp.x * dp, 1e-6 * dp) << where;
    EXPECT_NEAR(n.y, g_dp.y * dp, 1e-6 * dp) << where;
    EXPECT_NEAR(n.z, g_dp.z * dp, 1e-6 * dp) << where;
}

std::string errorOfCase(const std::string& tag, const std::string& mainlist, const std::string& extra,
                        std::string* xml = nullptr) {
    return test::buildError(writeCase(tag, mainlist, false, extra, xml));
}

std::string lineTag(const std::string& xml, const std::string& needle) {
    return "Case_Def.xml:" + std::to_string(test::lineOf(xml, needle)) + ":";
}

}  // namespace

TEST(GencaseNormals, TwoDimensionalTankFloorWallsAndCorners) {
    const GeneratedCase g = test::buildCase(writeCase("n2d", kTank2D, true, kNormals));
    const ParticleSet& p = g.particles;
    ASSERT_EQ(p.normal.size(), p.boundaryCount());
    ASSERT_EQ(p.normal.size(), g.count(ParticleType::Fixed));
    // Floor under the water at layer k (z = -(k-1) dp): the interface is at z = dp/2.
    for (int k = 1; k <= 3; ++k) {
        const double z = -(k - 1) * kDp;
        expectGhost(p, {1.0, 0, z}, {0, 0, 2.0 * k - 1});
        expectGhost(p, {0.3, 0, z}, {0, 0, 2.0 * k - 1});
        // Walls, halfway up and at their open top end (the top side stays flush).
        expectGhost(p, {-(k - 1) * kDp, 0, 0.5}, {2.0 * k - 1, 0, 0});
        expectGhost(p, {2.0 + (k - 1) * kDp, 0, 0.5}, {-(2.0 * k - 1), 0, 0});
        expectGhost(p, {-(k - 1) * kDp, 0, 1.5}, {2.0 * k - 1, 0, 0});
    }
    // Corners point diagonally at the interface's corner (dp/2, dp/2). Corner particles
    // farther than distanceh * h = 2 sqrt(2) dp from it have none: the offsets (2.5, 1.5),
    // (1.5, 2.5) and (2.5, 2.5) dp, three on each side.
    expectGhost(p, {0, 0, 0}, {1, 0, 1});
    expectGhost(p, {-0.1, 0, -0.1}, {3, 0, 3});
    expectGhost(p, {-0.2, 0, 0}, {5, 0, 1});
    expectGhost(p, {2.1, 0, -0.1}, {-3, 0, 3});
    expectGhost(p, {2.0, 0, -0.2}, {-1, 0, 5});
    expectGhost(p, {-0.2, 0, -0.1}, {0, 0, 0});
    expectGhost(p, {-0.2, 0, -0.2}, {0, 0, 0});
    expectGhost(p, {2.2, 0, -0.2}, {0, 0, 0});
    EXPECT_EQ(g.normals_set, "hdp");
    EXPECT_EQ(g.normals_stats.without_normal, 6u);
    EXPECT_EQ(g.normals_stats.with_normal, p.normal.size() - 6);
    EXPECT_NEAR(g.normals_stats.max_length / kDp, std::sqrt(26.0), 1e-6);  // the (5, 1) corners
    for (const Vec3f& n : p.normal) EXPECT_EQ(n.y, 0.0f);
    // drawshapes painted nothing: only the walls exist, 3 rows of 19 under the water and
    // 6 columns of 18.
    EXPECT_EQ(g.count(ParticleType::Fixed), 3u * 19 + 6u * 18);
}

TEST(GencaseNormals, ObstacleDrawnWithoutInvertHasOutwardNormals) {
    // A 0.6 m cube of particles (7 x 7 x 7) and its interface: all faces, grown by dp/2.
    const char* obstacle =
        "<setactive drawpoints=\"0\" drawshapes=\"1\"/><setshapemode>actual | bound</setshapemode>\n"
        "<setmkbound mk=\"1\"/><setnormalinvert invert=\"false\"/>\n"
        "<move x=\"1\" y=\"1\" z=\"0\"/>\n"
        "<drawbox><boxfill>all</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
        "<size x=\"0.6\" y=\"0.6\" z=\"0.6\"/><layers vdp=\"0.5\"/></drawbox>\n"
        "<shapeout file=\"hdp\"/><resetdraw/>\n"
        "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"1\" y=\"1\" z=\"0\"/>"
        "<size x=\"0.6\" y=\"0.6\" z=\"0.6\"/></drawbox>\n";
    const GeneratedCase g = test::buildCase(writeCase("n3d", obstacle, false, kNormals));
    const ParticleSet& p = g.particles;
    ASSERT_EQ(p.normal.size(), 343u);
    expectGhost(p, {1.0, 1.3, 0.3}, {-1, 0, 0});
    expectGhost(p, {1.6, 1.3, 0.3}, {1, 0, 0});
    expectGhost(p, {1.3, 1.0, 0.3}, {0, -1, 0});
    expectGhost(p, {1.3, 1.6, 0.3}, {0, 1, 0});
    expectGhost(p, {1.3, 1.3, 0.0}, {0, 0, -1});
    expectGhost(p, {1.3, 1.3, 0.6}, {0, 0, 1});
    expectGhost(p, {1.1, 1.3, 0.3}, {-3, 0, 0});
    // An edge particle of a convex body is dp/2 from three faces (a tie, decided by rounding):
    // its ghost vector is one of them, never the diagonal to the corner.
    const Vec3f e = p.normal[at(p, {1.0, 1.0, 0.6})];
    EXPECT_NEAR(std::sqrt(double(e.x) * e.x + double(e.y) * e.y + double(e.z) * e.z), kDp, 1e-6 * kDp);
    EXPECT_TRUE(e.x <= 0 && e.y <= 0 && e.z >= 0);
    // The centre is 3.5 dp from every face, beyond distanceh * h = 2 sqrt(3) dp.
    expectGhost(p, {1.3, 1.3, 0.3}, {0, 0, 0});
}

TEST(GencaseNormals, RotatedShapeFollowsTheTransform) {
    // A plate's top face (normal +z) rotated 90 degrees about y becomes the plane x = 2 with
    // normal +x, spanning z -1..0; the wall behind it gets ghost vectors along +x.
    const char* plate =
        "<setactive drawpoints=\"0\" drawshapes=\"1\"/><setmkbound mk=\"0\"/>"
        "<setnormalinvert invert=\"false\"/>\n"
        "<move x=\"2\" y=\"0\" z=\"0\"/><rotate ang=\"90\" x=\"0\" y=\"1\" z=\"0\"/>\n"
        "<drawbox><boxfill>top</boxfill><point x=\"0\" y=\"0\" z=\"-0.05\"/>"
        "<size x=\"1\" y=\"1\" z=\"0.05\"/></drawbox>\n"
        "<shapeout file=\"hdp\"/><resetdraw/>\n"
        "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"1.8\" y=\"0\" z=\"-0.5\"/>"
        "<size x=\"0.2\" y=\"0.5\" z=\"0\"/></drawbox>\n";
    const GeneratedCase g = test::buildCase(writeCase("nrot", plate, false, kNormals));
    // Local top face z = 0 maps to x = 2 (+ rounding of cos 90): particle x = 2.0 lies on it.
    expectGhost(g.particles, {1.9, 0.2, -0.5}, {2, 0, 0});
    expectGhost(g.particles, {1.8, 0.2, -0.5}, {4, 0, 0});
    expectGhost(g.particles, {2.0, 0.2, -0.5}, {0, 0, 0});
}

TEST(GencaseNormals, StarredLayersAndShapeModeSelectWhatIsRecorded) {
    // "0*,1" records only layer 0; a fluid MK is not recorded in "bound" shape mode.
    const char* cmds =
        "<setactive drawpoints=\"0\" drawshapes=\"1\"/><setshapemode>actual | bound</setshapemode>"
        "<setnormalinvert invert=\"true\"/>\n"
        "<setmkfluid mk=\"0\"/><drawbox><boxfill>bottom</boxfill><point x=\"0\" y=\"0\" z=\"0.3\"/>"
        "<size x=\"1\" y=\"1\" z=\"0\"/></drawbox>\n"
        "<setmkbound mk=\"0\"/><drawbox><boxfill>bottom</boxfill><point x=\"0\" y=\"0\" z=\"0.05\"/>"
        "<size x=\"1\" y=\"1\" z=\"1\"/><layers vdp=\"0*,1\"/></drawbox>\n"
        "<shapeout file=\"hdp\"/><resetdraw/>\n"
        "<setmkbound mk=\"0\"/><drawbox><boxfill>bottom</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
        "<size x=\"1\" y=\"1\" z=\"1\"/></drawbox>\n";
    const GeneratedCase g = test::buildCase(writeCase("nstar", cmds, false, kNormals));
    ASSERT_EQ(g.shapes.size(), 1u);
    EXPECT_EQ(g.shapes[0].faces.size(), 1u);
    expectGhost(g.particles, {0.5, 0.5, 0}, {0, 0, 1});
}

TEST(GencaseNormals, NoNormalsSectionOrInactiveLeavesNormalEmpty) {
    EXPECT_TRUE(test::buildCase(writeCase("nnone", kTank2D, true, "")).particles.normal.empty());
    std::string inactive = kNormals;
    inactive.replace(inactive.find("true"), 4, "false");
    EXPECT_TRUE(test::buildCase(writeCase("noff", kTank2D, true, inactive)).particles.normal.empty());
    // A missing active attribute means active (as in GenCase).
    std::string implicit = kNormals;
    implicit.replace(implicit.find(" active=\"true\""), 14, "");
    EXPECT_FALSE(test::buildCase(writeCase("nimpl", kTank2D, true, implicit)).particles.normal.empty());
}

TEST(GencaseNormals, OnlyFacesInFrontOfTheParticleCount) {
    // The unit square at z = 0 with its fluid side up (+z), distanceh * h = 0.3.
    ShapeFace up;
    up.u = {1, 0, 0};
    up.v = {0, 1, 0};
    up.normal = {0, 0, 1};
    const std::vector<Vec3d> pos = {{0.5, 0.5, -0.05}, {0.5, 0.5, 0.05}, {0.5, 0.5, 0.0},
                                    {1.2, 0.5, -0.05}, {0.5, 0.5, -0.31}, {0.5, 0.5, -0.3}};
    GhostVectorStats st;
    const std::vector<Vec3f> g = computeGhostVectors(pos, pos.size(), {up}, 0.3, kDp, false, "x", &st);
    auto expect = [&](std::size_t i, Vec3d v) {
        EXPECT_NEAR(g[i].x, v.x, 1e-7) << i;
        EXPECT_NEAR(g[i].y, v.y, 1e-7) << i;
        EXPECT_NEAR(g[i].z, v.z, 1e-7) << i;
    };
    expect(0, {0, 0, 0.1});     // behind: projection
    expect(1, {0, 0, 0});       // on the fluid side
    expect(2, {0, 0, 0});       // on the plane
    expect(3, {-0.4, 0, 0.1});  // beyond the edge: nearest edge point (1, 0.5, 0)
    expect(4, {0, 0, 0});       // farther than the reach
    expect(5, {0, 0, 0.6});     // exactly at the reach
    EXPECT_EQ(st.with_normal, 3u);
    EXPECT_EQ(st.without_normal, 3u);
    // A thin plate (top z = 0.05 facing up, bottom z = -0.05 facing down): a particle above
    // it is in front of the top face, so its ghost node mirrors it across the bottom face.
    ShapeFace top = up, bottom = up;
    top.origin = {0, 0, 0.05};
    bottom.origin = {0, 0, -0.05};
    std::swap(bottom.u, bottom.v);
    bottom.normal = {0, 0, -1};
    const std::vector<Vec3f> h = computeGhostVectors({{0.5, 0.5, 0.1}, {0.5, 0.5, 0.02}}, 2, {top, bottom}, 0.3,
                                                     kDp, false, "x", nullptr);
    EXPECT_NEAR(h[0].z, -0.3, 1e-7);
    EXPECT_NEAR(h[1].z, 0.06, 1e-7);
}

TEST(GencaseNormals, ResultDoesNotDependOnTheThreadCount) {
    const GeneratedCase g = test::buildCase(writeCase("nthr", kTank2D, true, kNormals));
    const ParticleSet& p = g.particles;
    const int saved = omp_get_max_threads();
    std::vector<std::vector<Vec3f>> runs;
    for (int threads : {1, 2, 3}) {
        omp_set_num_threads(threads);
        runs.push_back(computeGhostVectors(p.pos, p.boundaryCount(), g.shapes[0].faces, 2 * g.constants.h,
                                           kDp, true, "x", nullptr));
    }
    omp_set_num_threads(saved);
    for (std::size_t r = 1; r < runs.size(); ++r)
        for (std::size_t i = 0; i < runs[0].size(); ++i) {
            ASSERT_EQ(std::memcmp(&runs[0][i], &runs[r][i], sizeof(Vec3f)), 0) << "particle " << i;
            ASSERT_EQ(std::memcmp(&runs[0][i], &p.normal[i], sizeof(Vec3f)), 0) << "particle " << i;
        }
}

TEST(GencaseNormals, Hdf5RoundTripAndShapeFile) {
    const std::string def = writeCase("nh5", kTank2D, true, kNormals);
    std::ostringstream log;
    auto builder = test::buildCaseKeepBuilder(def, log);
    builder->write();
    EXPECT_HAS(log.str(), "Normals (mDBC, shape set 'hdp')");
    const std::string dir = fs::path(def).parent_path().string() + "/out";
    const io::CaseFileContents c = io::readCaseH5(dir + "/Case.h5");
    const ParticleSet& p = builder->result().particles;
    ASSERT_EQ(c.particles.normal.size(), p.normal.size());
    EXPECT_EQ(std::memcmp(c.particles.normal.data(), p.normal.data(), p.normal.size() * sizeof(Vec3f)), 0);
    // The shape set as GenCase names it, legacy VTK with one quad per face.
    std::ifstream vtk(dir + "/Case_hdp_Actual.vtk");
    ASSERT_TRUE(vtk.good());
    std::stringstream text;
    text << vtk.rdbuf();
    EXPECT_HAS(text.str(), "DATASET POLYDATA");
    EXPECT_HAS(text.str(), "POLYGONS 3 15");

    // A count that does not match the non-fluid particles, and a non-finite value.
    const std::size_t nbound = p.normal.size();
    {
        io::h5::File f = io::h5::File::openReadWrite(dir + "/Case.h5");
        io::h5::Location g = f.openGroup("particles");
        g.removeChild("normal");
        io::h5::writeDataset(g, "normal", reinterpret_cast<const float*>(p.normal.data()), nbound - 1, 3);
    }
    std::string e = test::errorOf([&] { io::readCaseH5(dir + "/Case.h5"); });
    EXPECT_HAS(e, "Case.h5");
    EXPECT_HAS(e, "/particles/normal has " + std::to_string(nbound - 1) + " entries");
    {
        io::h5::File f = io::h5::File::openReadWrite(dir + "/Case.h5");
        io::h5::Location g = f.openGroup("particles");
        g.removeChild("normal");
        std::vector<Vec3f> bad = p.normal;
        bad[4].z = std::nanf("");
        io::h5::writeDataset(g, "normal", reinterpret_cast<const float*>(bad.data()), nbound, 3);
    }
    e = test::errorOf([&] { io::readCaseH5(dir + "/Case.h5"); });
    EXPECT_HAS(e, "/particles/normal[4]");
    EXPECT_HAS(e, "not finite");
    // Writing checks the same.
    ParticleSet wrong = p;
    wrong.normal.pop_back();
    io::CaseFileHeader h{"Case", 2, kDp, wrong.size(), "test"};
    e = test::errorOf([&] { io::writeCaseH5(dir + "/Wrong.h5", h, wrong, nullptr); });
    EXPECT_HAS(e, "Wrong.h5");
    EXPECT_HAS(e, "/particles/normal");
    // Without normals no dataset is written and none is read back.
    ParticleSet plain = p;
    plain.normal.clear();
    io::writeCaseH5(dir + "/Plain.h5", h, plain, nullptr);
    EXPECT_TRUE(io::readCaseH5(dir + "/Plain.h5").particles.normal.empty());
    EXPECT_FALSE(io::h5::File::openReadOnly(dir + "/Plain.h5").openGroup("particles").hasChild("normal"));
}

TEST(GencaseNormals, ErrorsNameFileLineAndElement) {
    std::string xml;
    // A shape other than drawbox while shapes are recorded.
    std::string e = errorOfCase("ne1",
        "<setactive drawpoints=\"0\" drawshapes=\"1\"/><setmkbound mk=\"0\"/>\n"
        "<drawcylinder radius=\"0.2\"><point x=\"0\" y=\"0\" z=\"0\"/><point x=\"0\" y=\"0\" z=\"1\"/></drawcylinder>",
        "", &xml);
    EXPECT_HAS(e, lineTag(xml, "<drawcylinder"));
    EXPECT_HAS(e, "<drawcylinder>");
    EXPECT_HAS(e, "normals geometry supports drawbox only");
    // geometryfile naming a set no shapeout wrote.
    const std::string unknown_set =
        "<normals active=\"true\">\n<geometryfile file=\"[CaseName]_nope_Actual.vtk\"/></normals>";
    e = errorOfCase("ne2", kTank2D, unknown_set, &xml);
    EXPECT_HAS(e, lineTag(xml, "<geometryfile"));
    EXPECT_HAS(e, "no shape set 'nope'");
    EXPECT_HAS(e, "'hdp'");
    // An unknown child of <normals>.
    e = errorOfCase("ne3", kTank2D,
                    "<normals active=\"true\">\n<norplane mkbound=\"0\"/>\n"
                    "<geometryfile file=\"[CaseName]_hdp_Actual.vtk\"/></normals>", &xml);
    EXPECT_HAS(e, lineTag(xml, "<norplane"));
    EXPECT_HAS(e, "<norplane>");
    // No geometryfile.
    e = errorOfCase("ne4", kTank2D, "<normals active=\"true\">\n<distanceh value=\"2\"/></normals>", &xml);
    EXPECT_HAS(e, lineTag(xml, "<normals"));
    EXPECT_HAS(e, "geometryfile");
    // A set that exists but is empty (shapes were never switched on).
    e = errorOfCase("ne5",
                    "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
                    "<size x=\"1\" y=\"1\" z=\"0\"/></drawbox><shapeout file=\"hdp\"/>",
                    kNormals, &xml);
    EXPECT_HAS(e, "has no faces");
    EXPECT_HAS(e, "drawshapes");
    // An external VTK file (exists) is not supported yet.
    const std::string dir = test::scratchDir("ne6");
    test::writeFile(dir, "wall.vtk", "# vtk DataFile Version 3.0\n");
    xml = test::caseXml(kTank2D, kDp, true, "<normals>\n<geometryfile file=\"wall.vtk\"/></normals>");
    e = test::buildError(test::writeFile(dir, "Case_Def.xml", xml));
    EXPECT_HAS(e, lineTag(xml, "<geometryfile"));
    EXPECT_HAS(e, "external VTK geometry");
    // distanceh must be positive.
    e = errorOfCase("ne7", kTank2D,
                    "<normals>\n<distanceh value=\"0\"/><geometryfile file=\"[CaseName]_hdp_Actual.vtk\"/></normals>",
                    &xml);
    EXPECT_HAS(e, lineTag(xml, "<distanceh"));
    // setnormalinvert needs its attribute; a dp-only shape mode cannot record shapes.
    e = errorOfCase("ne8", "<setnormalinvert/>", "", &xml);
    EXPECT_HAS(e, lineTag(xml, "<setnormalinvert"));
    e = errorOfCase("ne9",
                    "<setactive drawshapes=\"1\"/><setshapemode>dp | bound</setshapemode><setmkbound mk=\"0\"/>\n"
                    "<drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
                    "<size x=\"1\" y=\"1\" z=\"0\"/></drawbox>",
                    "", &xml);
    EXPECT_HAS(e, lineTag(xml, "<drawbox"));
    EXPECT_HAS(e, "actual");
}

TEST(GencaseNormals, SphericTest2WallsTouchingTheFluidGetNormals) {
    const std::string src = std::string(SEASPRING_SHARED_DIR) + "/dualsphysics-cases/Spheric2Dam_100K.xml";
    if (!fs::exists(src)) GTEST_SKIP() << src << " is missing (real DualSPHysics cases not present)";
    std::ifstream in(src);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string xml = ss.str();
    const std::string off = "<normals active=\"false\">";
    ASSERT_NE(xml.find(off), std::string::npos);
    xml.replace(xml.find(off), off.size(), "<normals active=\"true\">");
    const GeneratedCase g = test::buildCase(test::writeFile(test::scratchDir("nsph"), "Case_Def.xml", xml));
    const ParticleSet& p = g.particles;
    const double dp = g.constants.dp;
    ASSERT_EQ(p.normal.size(), p.boundaryCount());
    ASSERT_EQ(p.normal.size(), 77346u);
    // Every first-layer floor particle under the water block (x >= 1.992, away from the
    // side walls) has ghost vector (0, 0, dp).
    std::size_t floor = 0;
    for (std::size_t i = 0; i < p.normal.size(); ++i) {
        const Vec3d x = p.pos[i];
        if (std::fabs(x.z) > 1e-9 || x.x < 1.992 || x.x > 3.22 - 0.5 * dp || x.y < 0.5 * dp || x.y > 1 - 0.5 * dp)
            continue;
        ++floor;
        EXPECT_NEAR(p.normal[i].x, 0, 1e-6 * dp) << i;
        EXPECT_NEAR(p.normal[i].y, 0, 1e-6 * dp) << i;
        EXPECT_NEAR(p.normal[i].z, dp, 1e-6 * dp) << i;
    }
    EXPECT_EQ(floor, 49u * 39u);
    // Every boundary particle next to a fluid particle (26-neighbourhood) has a normal.
    std::set<std::tuple<long, long, long>> fluid;
    auto key = [&](Vec3d x) {
        return std::make_tuple(std::lround(x.x / dp), std::lround(x.y / dp), std::lround(x.z / dp));
    };
    for (std::size_t i = p.normal.size(); i < p.size(); ++i) fluid.insert(key(p.pos[i]));
    std::size_t touching = 0;
    for (std::size_t i = 0; i < p.normal.size(); ++i) {
        const auto [kx, ky, kz] = key(p.pos[i]);
        bool near = false;
        for (long dx = -1; dx <= 1 && !near; ++dx)
            for (long dy = -1; dy <= 1 && !near; ++dy)
                for (long dz = -1; dz <= 1 && !near; ++dz) near = fluid.count({kx + dx, ky + dy, kz + dz}) > 0;
        if (!near) continue;
        ++touching;
        const Vec3f n = p.normal[i];
        EXPECT_GT(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z, 0.25 * dp * dp) << "particle " << i;
    }
    EXPECT_GT(touching, 2000u);
    // The obstacle (mkbound 1): its left face points along -x, out of the obstacle.
    double xmin = 1e9;
    for (std::size_t i = 0; i < p.normal.size(); ++i)
        if (p.mk[i] == 11) xmin = std::min(xmin, p.pos[i].x);
    std::size_t left = 0;
    for (std::size_t i = 0; i < p.normal.size(); ++i) {
        const Vec3d x = p.pos[i];
        if (p.mk[i] != 11 || std::fabs(x.x - xmin) > 1e-9 || x.z < 2 * dp || x.z > 0.1 || x.y < 0.33 || x.y > 0.67)
            continue;
        ++left;
        EXPECT_NEAR(p.normal[i].x, -dp, 1e-6 * dp) << i;
        EXPECT_NEAR(p.normal[i].y, 0, 1e-6 * dp) << i;
        EXPECT_NEAR(p.normal[i].z, 0, 1e-6 * dp) << i;
    }
    EXPECT_GT(left, 0u);
}
