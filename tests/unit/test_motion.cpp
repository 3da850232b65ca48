// SeaSpring — MIT licence.
/// \file test_motion.cpp
/// \brief Tests of the <motion> parser: shared DualSPHysics cases, every movement kind,
///        normalized write/read round trip, and every error path.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "case/motion_xml.h"
#include "core/error.h"
#include "gencase/motion.h"

using namespace seaspring;
using namespace seaspring::gencase;
using namespace seaspring::model;

namespace {

const double kPi = 3.14159265358979323846;

/// Removes the scratch directory when the test process ends.
struct ScratchCleanup {
    std::string dir;
    ~ScratchCleanup() {
        std::error_code ec;
        if (!dir.empty()) std::filesystem::remove_all(dir, ec);
    }
};

std::string tmpDir() {
    static ScratchCleanup cleanup;
    static const std::string dir = [] {
        // One directory per process: ctest runs each test case as its own process, in parallel.
        const std::string d =
            ::testing::TempDir() + "seaspring_test_motion_" + std::to_string(::getpid());
        ::mkdir(d.c_str(), 0755);
        ::mkdir((d + "/sub").c_str(), 0755);
        cleanup.dir = d;
        return d;
    }();
    return dir;
}

std::string writeFile(const std::string& name, const std::string& text) {
    const std::string path = tmpDir() + "/" + name;
    std::ofstream(path) << text;
    return path;
}

bool dirExists(const std::string& d) {
    struct stat st {};
    return ::stat(d.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

/// Writes `xml` (root element <motion>) to the temporary directory and parses it.
MotionSet parseText(const std::string& name, const std::string& xml,
                    const ExpressionEvaluator& ev = {}) {
    const XmlSource src(writeFile(name, xml));
    return parseMotion(src, src.root(), ev);
}

/// Parses and expects an Error whose message contains every part.
void expectError(const std::string& name, const std::string& xml,
                 const std::vector<std::string>& parts) {
    try {
        parseText(name, xml);
        ADD_FAILURE() << name << ": no error";
    } catch (const Error& e) {
        const std::string msg = e.what();
        for (const std::string& p : parts)
            EXPECT_NE(msg.find(p), std::string::npos) << "missing '" << p << "' in: " << msg;
    }
}

/// An object ref=3 whose movements (`body`) start at line 4.
std::string inObject(const std::string& body, const std::string& begin = "mov=\"1\" start=\"0\"") {
    return "<motion>\n  <objreal ref=\"3\">\n    <begin " + begin + "/>\n" + body +
           "  </objreal>\n</motion>\n";
}

void expectVec(Vec3d v, double x, double y, double z) {
    EXPECT_EQ(v.x, x);
    EXPECT_EQ(v.y, y);
    EXPECT_EQ(v.z, z);
}

void expectSame(const MotionSet& a, const MotionSet& b) {
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const MotionObject &p = a.objects[i], &q = b.objects[i];
        EXPECT_EQ(p.mkbound, q.mkbound);
        EXPECT_EQ(p.first_movement, q.first_movement);
        EXPECT_EQ(p.start, q.start);
        EXPECT_EQ(p.finish, q.finish);
        EXPECT_EQ(p.line, q.line);
        ASSERT_EQ(p.movements.size(), q.movements.size());
        for (std::size_t j = 0; j < p.movements.size(); ++j) {
            const Movement &m = p.movements[j], &n = q.movements[j];
            SCOPED_TRACE("object " + std::to_string(i) + " movement " + std::to_string(j));
            EXPECT_EQ(m.id, n.id);
            EXPECT_EQ(m.kind, n.kind);
            EXPECT_EQ(m.duration, n.duration);
            EXPECT_EQ(m.next, n.next);
            EXPECT_EQ(m.has_velini, n.has_velini);
            EXPECT_EQ(m.has_phase, n.has_phase);
            for (auto f :
                 {&Movement::vel, &Movement::velini, &Movement::ace, &Movement::freq,
                  &Movement::ampl, &Movement::phase, &Movement::axis_p1, &Movement::axis_p2})
                expectVec(m.*f, (n.*f).x, (n.*f).y, (n.*f).z);
            EXPECT_EQ(m.ang_vel, n.ang_vel);
            EXPECT_EQ(m.ang_freq, n.ang_freq);
            EXPECT_EQ(m.ang_ampl, n.ang_ampl);
            EXPECT_EQ(m.ang_phase, n.ang_phase);
            EXPECT_EQ(m.table.time, n.table.time);
            ASSERT_EQ(m.table.value.size(), n.table.value.size());
            for (std::size_t k = 0; k < m.table.value.size(); ++k)
                expectVec(m.table.value[k], n.table.value[k].x, n.table.value[k].y,
                          n.table.value[k].z);
            EXPECT_EQ(m.source_file, n.source_file);
            EXPECT_EQ(m.line, n.line);
        }
    }
}

/// Writes the normalized form to a file and reads it back.
MotionSet roundTrip(const MotionSet& set, const std::string& name) {
    pugi::xml_document doc;
    writeMotion(set, doc.append_child("case"));
    const std::string path = tmpDir() + "/" + name;
    EXPECT_TRUE(doc.save_file(path.c_str()));
    const XmlSource src(path);
    return readMotion(src, src.root().child("motion"));
}

// Every supported kind; line numbers are used below.
const char* kAllKinds = R"(<motion comment="all kinds">
  <objreal ref="5">
    <begin mov="1" start="#t0" finish="#t0+10"/>
    <mvrect id="1" duration="0.5" next="2"><vel x="1" y="#vy" z="-0.5"/></mvrect>
    <mvrectace id="2" duration="1" next="3"><velini x="0.5" y="0" z="0"/><ace x="0" y="0" z="-2"/></mvrectace>
    <mvrectace id="3" duration="1" next="4"><ace x="1" y="0" z="0"/></mvrectace>
    <mvrot id="4" duration="2" next="5"><vel ang="90"/><axisp1 x="0" y="0" z="0"/><axisp2 x="0" y="1" z="0"/></mvrot>
    <mvrotsinu id="5" duration="3" next="6" anglesunits="radians"><freq v="0.5"/><ampl v="0.25"/><phase v="1.5"/><axisp1 x="1" y="0" z="0"/><axisp2 x="1" y="0" z="1"/></mvrotsinu>
    <mvrectsinu id="6" duration="4" next="7"><freq x="1" y="0" z="2"/><ampl x="0.1" y="0" z="0.2"/><phase x="180" y="0" z="-90"/></mvrectsinu>
    <mvsinu id="7" duration="1" next="8" anglesunits="radians"><freq x="0.5" y="0.5" z="0.5"/><ampl x="1" y="2" z="3"/></mvsinu>
    <_mvcir id="99" duration="1"/>
    <wait id="8" duration="0.75" next="9" comment="pause"/>
    <mvfile id="9" duration="1" next="10"><file name="@PADDLE@" fields="4" fieldtime="0" fieldx="2" fieldy="1"/></mvfile>
    <mvrectfile id="10" duration="2" next="11"><file name="sub/gate.csv" fields="2" fieldtime="0" fieldz="1"/></mvrectfile>
    <mvrotfile id="11" duration="5" next="1" anglesunits="radians"><file name="rot.csv"/><axisp1 x="0" y="0" z="0"/><axisp2 x="0" y="0" z="1"/></mvrotfile>
  </objreal>
  <objreal ref="7">
    <begin mov="1" start="0"/>
    <mvnull id="1"/>
  </objreal>
</motion>
)";

MotionSet parseAllKinds() {
    writeFile("sub/gate.csv", "0, 0\n0.5, 0.25\n");
    writeFile("rot.csv", "# angle in radians\n0\t0\n0.5\t0.25\n\n1\t-0.5\n");
    std::string xml = kAllKinds;
    const std::string paddle = std::string(SEASPRING_TEST_DATA_DIR) + "/motion/paddle_header.csv";
    xml.replace(xml.find("@PADDLE@"), 8, paddle);
    ExpressionEvaluator ev;
    ev.define("t0", 0.5);
    ev.define("vy", 2);
    return parseText("all_kinds.xml", xml, ev);
}

}  // namespace

TEST(Motion, SharedDambreak2DGateFile) {
    const std::string dir = std::string(SEASPRING_SHARED_DIR) + "/dualsphysics-cases/flexstruc";
    if (!dirExists(dir)) GTEST_SKIP() << dir << " not found";
    const XmlSource src(dir + "/CaseDambreak2D_FSI_Def.xml");
    const MotionSet set =
        parseMotion(src, src.root().child("casedef").child("motion"), ExpressionEvaluator{});
    ASSERT_EQ(set.objects.size(), 2u);
    const MotionObject* gate = set.find(0);
    ASSERT_NE(gate, nullptr);
    EXPECT_EQ(gate->line, 63);
    EXPECT_EQ(gate->first_movement, 1);
    EXPECT_EQ(gate->start, 0.0);
    EXPECT_EQ(gate->finish, 0.12);
    ASSERT_EQ(gate->movements.size(), 1u);
    const Movement& m = gate->movements[0];
    EXPECT_EQ(m.kind, MovementKind::RectFile);
    EXPECT_EQ(m.duration, 0.12);
    EXPECT_EQ(m.next, -1);
    EXPECT_EQ(m.line, 65);
    EXPECT_EQ(m.source_file, dir + "/DambreakGateTimeSeries.csv");
    ASSERT_EQ(m.table.time.size(), 101u);
    EXPECT_EQ(m.table.time[0], 0.0);
    expectVec(m.table.value[0], 0, 0, 0);
    EXPECT_EQ(m.table.time[1], 1.5e-3);
    expectVec(m.table.value[1], 0, 0, 3.811739868750e-04);
    EXPECT_EQ(m.table.time[100], 0.15);
    expectVec(m.table.value[100], 0, 0, 0.686544375);
    const MotionObject* solid = set.find(2);
    ASSERT_NE(solid, nullptr);
    ASSERT_EQ(solid->movements.size(), 1u);
    EXPECT_EQ(solid->movements[0].kind, MovementKind::Null);
    EXPECT_EQ(solid->movements[0].duration, -1.0);
    EXPECT_EQ(solid->movements[0].next, -1);
    EXPECT_TRUE(std::isinf(solid->finish));
    EXPECT_EQ(set.find(1), nullptr);
    expectSame(set, roundTrip(set, "dambreak_normalized.xml"));
}

TEST(Motion, SharedRollingTankDegreesToRadians) {
    const std::string dir = std::string(SEASPRING_SHARED_DIR) + "/dualsphysics-cases/flexstruc";
    if (!dirExists(dir)) GTEST_SKIP() << dir << " not found";
    const XmlSource src(dir + "/CaseRollingTankHanging_Def.xml");
    const MotionSet set =
        parseMotion(src, src.root().child("casedef").child("motion"), ExpressionEvaluator{});
    ASSERT_EQ(set.objects.size(), 2u);
    const Movement& m = set.objects[0].movements.at(0);
    EXPECT_EQ(set.objects[0].mkbound, 0);
    EXPECT_EQ(m.kind, MovementKind::RotFile);
    EXPECT_EQ(m.duration, 100.0);
    expectVec(m.axis_p1, 0.3045, -0.01, 0);
    expectVec(m.axis_p2, 0.3045, 0.02, 0);
    ASSERT_EQ(m.table.time.size(), 599u);
    EXPECT_EQ(m.table.time[0], 0.009995889690);
    EXPECT_NEAR(m.table.value[0].x, -2.3594992606590206e-05, 1e-18);  // -0.001351893494 deg
    EXPECT_EQ(m.table.time[598], 5.989033541);
    EXPECT_NEAR(m.table.value[598].x, 0.006043323084921801, 1e-17);  // 0.3462569070 deg
    EXPECT_EQ(m.table.value[598].y, 0.0);
    EXPECT_EQ(set.objects[1].mkbound, 1);
    EXPECT_EQ(set.objects[1].movements.at(0).kind, MovementKind::Null);
    expectSame(set, roundTrip(set, "rolling_normalized.xml"));
}

TEST(Motion, EveryKind) {
    const MotionSet set = parseAllKinds();
    ASSERT_EQ(set.objects.size(), 2u);
    const MotionObject& o = set.objects[0];
    EXPECT_EQ(o.mkbound, 5);
    EXPECT_EQ(o.line, 2);
    EXPECT_EQ(o.start, 0.5);
    EXPECT_EQ(o.finish, 10.5);
    ASSERT_EQ(o.movements.size(), 11u);  // the commented-out <_mvcir> is skipped
    const std::vector<Movement>& v = o.movements;
    for (int i = 0; i < 11; ++i) EXPECT_EQ(v[i].id, i + 1);
    const MovementKind kinds[] = {
        MovementKind::Rect,     MovementKind::RectAce,  MovementKind::RectAce,  MovementKind::Rot,
        MovementKind::RotSinu,  MovementKind::RectSinu, MovementKind::RectSinu, MovementKind::Wait,
        MovementKind::RectFile, MovementKind::RectFile, MovementKind::RotFile};
    const double durations[] = {0.5, 1, 1, 2, 3, 4, 1, 0.75, 1, 2, 5};
    const int nexts[] = {2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 1};
    const int lines[] = {4, 5, 6, 7, 8, 9, 10, 12, 13, 14, 15};
    for (int i = 0; i < 11; ++i) {
        EXPECT_EQ(v[i].kind, kinds[i]) << i;
        EXPECT_EQ(v[i].duration, durations[i]) << i;
        EXPECT_EQ(v[i].next, nexts[i]) << i;
        EXPECT_EQ(v[i].line, lines[i]) << i;
    }
    expectVec(v[0].vel, 1, 2, -0.5);
    EXPECT_TRUE(v[1].has_velini);
    expectVec(v[1].velini, 0.5, 0, 0);
    expectVec(v[1].ace, 0, 0, -2);
    EXPECT_FALSE(v[2].has_velini);
    expectVec(v[2].ace, 1, 0, 0);
    EXPECT_DOUBLE_EQ(v[3].ang_vel, kPi / 2);  // 90 degrees/s, degrees by default
    expectVec(v[3].axis_p2, 0, 1, 0);
    EXPECT_EQ(v[4].ang_freq, 0.5);
    EXPECT_EQ(v[4].ang_ampl, 0.25);
    EXPECT_TRUE(v[4].has_phase);
    EXPECT_EQ(v[4].ang_phase, 1.5);
    expectVec(v[4].axis_p1, 1, 0, 0);
    expectVec(v[4].axis_p2, 1, 0, 1);
    expectVec(v[5].freq, 1, 0, 2);
    expectVec(v[5].ampl, 0.1, 0, 0.2);
    EXPECT_TRUE(v[5].has_phase);
    EXPECT_DOUBLE_EQ(v[5].phase.x, kPi);
    EXPECT_EQ(v[5].phase.y, 0.0);
    EXPECT_DOUBLE_EQ(v[5].phase.z, -kPi / 2);
    EXPECT_FALSE(v[6].has_phase);
    expectVec(v[6].phase, 0, 0, 0);
    expectVec(v[6].ampl, 1, 2, 3);
    // mvfile: columns time;posy;posx;unused with a header line and trailing ';'.
    EXPECT_EQ(v[8].source_file, std::string(SEASPRING_TEST_DATA_DIR) + "/motion/paddle_header.csv");
    EXPECT_EQ(v[8].table.time, (std::vector<double>{0, 0.25, 1}));
    ASSERT_EQ(v[8].table.value.size(), 3u);
    expectVec(v[8].table.value[0], 1.5, 0.5, 0);
    expectVec(v[8].table.value[1], 2.5, -0.5, 0);
    expectVec(v[8].table.value[2], 3, 0.125, 0);
    EXPECT_EQ(v[9].source_file, tmpDir() + "/sub/gate.csv");
    EXPECT_EQ(v[9].table.time, (std::vector<double>{0, 0.5}));
    expectVec(v[9].table.value[1], 0, 0, 0.25);
    EXPECT_EQ(v[10].table.time, (std::vector<double>{0, 0.5, 1}));
    expectVec(v[10].table.value[2], -0.5, 0, 0);
    expectVec(v[10].axis_p2, 0, 0, 1);
    const MotionObject* still = set.find(7);
    ASSERT_NE(still, nullptr);
    EXPECT_EQ(still->movements.at(0).kind, MovementKind::Null);
    EXPECT_EQ(still->movements.at(0).line, 19);
    EXPECT_EQ(o.movement(11), &v[10]);
    EXPECT_EQ(o.movement(12), nullptr);
}

TEST(Motion, NormalizedRoundTripIsExact) {
    const MotionSet set = parseAllKinds();
    pugi::xml_document doc;
    writeMotion(set, doc.append_child("case"));
    const pugi::xml_node o = doc.child("case").child("motion").child("objreal");
    EXPECT_STREQ(o.child("begin").attribute("finish").value(), "10.5");
    EXPECT_STREQ(o.child("mvrot").attribute("anglesunits").value(), "radians");
    EXPECT_STREQ(o.child("mvrot").child("vel").attribute("ang").value(), "1.5707963267948966");
    EXPECT_STREQ(o.child("mvrectfile").child("table").attribute("rows").value(), "3");
    EXPECT_FALSE(o.child("mvfile"));  // canonical names only
    const pugi::xml_node still = o.next_sibling("objreal");
    EXPECT_STREQ(still.child("begin").attribute("finish").value(), "-1");
    const MotionSet back = roundTrip(set, "all_kinds_normalized.xml");
    expectSame(set, back);
    EXPECT_FALSE(back.objects[0].movements[2].has_velini);
    EXPECT_FALSE(back.objects[0].movements[6].has_phase);
    expectSame(back, roundTrip(back, "all_kinds_normalized2.xml"));
}

TEST(Motion, ReadNormalizedRejectsWrongRowCount) {
    const std::string path = writeFile(
        "bad_norm.xml",
        "<motion>\n<objreal ref=\"0\" line=\"9\">\n<begin mov=\"1\" start=\"0\" finish=\"-1\"/>\n"
        "<mvrotfile id=\"1\" duration=\"1\" next=\"0\" anglesunits=\"radians\" line=\"10\" "
        "source=\"x\">\n"
        "<table rows=\"3\" columns=\"2\">\n0 1\n1 2\n</table>\n"
        "<axisp1 x=\"0\" y=\"0\" z=\"0\"/><axisp2 x=\"0\" y=\"1\" "
        "z=\"0\"/>\n</mvrotfile>\n</objreal>\n</motion>\n");
    const XmlSource src(path);
    try {
        readMotion(src, src.root());
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path + ":5"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("rows=\"3\""), std::string::npos) << e.what();
    }
}

TEST(Motion, StructureErrors) {
    const std::string d = tmpDir() + "/";
    expectError("e_nested.xml", inObject("    <obj>\n    </obj>\n"),
                {d + "e_nested.xml:4", "<obj>", "not supported"});
    expectError("e_group.xml", "<motion>\n  <obj>\n  </obj>\n</motion>\n",
                {d + "e_group.xml:2", "<obj>", "not supported"});
    for (const char* u :
         {"mvcir", "mvcirace", "mvcirsinu", "mvrotace", "mvrotadvfile", "mvpathfile"})
        expectError(
            "e_unsup.xml",
            inObject(std::string("    <wait id=\"1\" duration=\"1\"/>\n    <") + u +
                     " id=\"2\"/>\n"),
            {d + "e_unsup.xml:5", std::string("<") + u + ">", "not supported by SeaSpring"});
    expectError("e_unknown.xml", inObject("    <mvspin id=\"1\"/>\n"),
                {d + "e_unknown.xml:4", "<mvspin>"});
    expectError("e_top.xml", "<motion>\n  <begin mov=\"1\"/>\n</motion>\n",
                {d + "e_top.xml:2", "<begin>"});
    expectError("e_ref.xml",
                "<motion>\n  <objreal ref=\"3\">\n    <begin mov=\"1\" start=\"0\"/>\n    <mvnull "
                "id=\"1\"/>\n  </objreal>\n"
                "  <objreal ref=\"3\">\n    <begin mov=\"1\" start=\"0\"/>\n    <mvnull "
                "id=\"1\"/>\n  </objreal>\n</motion>\n",
                {d + "e_ref.xml:6", "ref=\"3\"", "line 2"});
    expectError(
        "e_dupid.xml",
        inObject("    <wait id=\"1\" duration=\"1\"/>\n    <wait id=\"1\" duration=\"2\"/>\n"),
        {d + "e_dupid.xml:5", "id=\"1\"", "line 4"});
    expectError("e_mov.xml",
                inObject("    <wait id=\"1\" duration=\"1\"/>\n", "mov=\"2\" start=\"0\""),
                {d + "e_mov.xml:3", "mov=\"2\"", "ids of ref=3: 1"});
    expectError("e_next.xml", inObject("    <wait id=\"1\" duration=\"1\" next=\"7\"/>\n"),
                {d + "e_next.xml:4", "next=\"7\"", "ids of ref=3: 1"});
    expectError(
        "e_nobegin.xml",
        "<motion>\n  <objreal ref=\"1\">\n    <mvnull id=\"1\"/>\n  </objreal>\n</motion>\n",
        {d + "e_nobegin.xml:2", "<begin"});
    expectError("e_begin2.xml",
                inObject("    <begin mov=\"1\" start=\"1\"/>\n    <mvnull id=\"1\"/>\n"),
                {d + "e_begin2.xml:4", "line 3", "one <begin>"});
    expectError("e_id0.xml", inObject("    <mvnull id=\"0\"/>\n"),
                {d + "e_id0.xml:4", "id=\"0\"", ">= 1"});
    expectError("e_attr.xml", inObject("    <wait id=\"1\" duration=\"1\" speed=\"3\"/>\n"),
                {d + "e_attr.xml:4", "speed=\"3\""});
    expectError("e_child.xml",
                inObject("    <mvrect id=\"1\" duration=\"1\"><vel x=\"1\" y=\"0\" z=\"0\"/><acc "
                         "x=\"1\" y=\"0\" z=\"0\"/></mvrect>\n"),
                {d + "e_child.xml:4", "<acc>"});
    expectError("e_twice.xml",
                inObject("    <mvrect id=\"1\" duration=\"1\"><vel x=\"1\" y=\"0\" z=\"0\"/>\n<vel "
                         "x=\"2\" y=\"0\" z=\"0\"/></mvrect>\n"),
                {d + "e_twice.xml:5", "<vel>", "line 4"});
    expectError("e_finish.xml",
                inObject("    <mvnull id=\"1\"/>\n", "mov=\"1\" start=\"2\" finish=\"1\""),
                {d + "e_finish.xml:3", "finish=\"1\""});
    expectError("e_finexpr.xml",
                inObject("    <mvnull id=\"1\"/>\n", "mov=\"1\" start=\"1\" finish=\"#0.5*1\""),
                {d + "e_finexpr.xml:3", "finish=\"#0.5*1\" (= 0.5)", "start (1)"});
    expectError("e_start.xml", inObject("    <mvnull id=\"1\"/>\n", "mov=\"1\" start=\"-1\""),
                {d + "e_start.xml:3", "start=\"-1\""});
}

TEST(Motion, ValueErrors) {
    const std::string d = tmpDir() + "/";
    expectError("e_dur.xml", inObject("    <wait id=\"1\" duration=\"-2\"/>\n"),
                {d + "e_dur.xml:4", "duration=\"-2\""});
    expectError("e_expr.xml", inObject("    <wait id=\"1\" duration=\"#nosuch*2\"/>\n"),
                {d + "e_expr.xml:4", "nosuch"});
    expectError(
        "e_axis.xml",
        inObject(
            "    <mvrot id=\"1\" duration=\"1\"><vel ang=\"1\"/><axisp1 x=\"1\" y=\"2\" z=\"3\"/>\n"
            "      <axisp2 x=\"1\" y=\"2\" z=\"3\"/></mvrot>\n"),
        {d + "e_axis.xml:5", "(1,2,3)", "<axisp2>"});
    expectError("e_units.xml",
                inObject("    <mvrot id=\"1\" duration=\"1\" anglesunits=\"grads\"><vel "
                         "ang=\"1\"/><axisp1 x=\"0\" y=\"0\" z=\"0\"/>"
                         "<axisp2 x=\"0\" y=\"0\" z=\"1\"/></mvrot>\n"),
                {d + "e_units.xml:4", "anglesunits=\"grads\"", "degrees or radians"});
    expectError("e_field.xml",
                inObject("    <mvfile id=\"1\" duration=\"1\">\n      <file name=\"x.csv\" "
                         "fields=\"2\" fieldtime=\"0\" fieldz=\"2\"/>\n    </mvfile>\n"),
                {d + "e_field.xml:5", "fieldz=\"2\"", "fields-1 = 1"});
    expectError("e_nofield.xml",
                inObject("    <mvfile id=\"1\" duration=\"1\">\n      <file name=\"x.csv\" "
                         "fields=\"2\" fieldtime=\"0\"/>\n    </mvfile>\n"),
                {d + "e_nofield.xml:5", "fieldx, fieldy, fieldz"});
}

TEST(Motion, DataFileErrors) {
    const std::string d = tmpDir() + "/";
    const auto mvfile = [](const std::string& csv, int fields) {
        return inObject("    <mvfile id=\"1\" duration=\"1\">\n      <file name=\"" + csv +
                        "\" fields=\"" + std::to_string(fields) +
                        "\" fieldtime=\"0\" fieldx=\"1\"/>\n    </mvfile>\n");
    };
    writeFile("few.csv", "0;1;2\n1;2\n");
    expectError(
        "e_few.xml", mvfile("few.csv", 3),
        {d + "few.csv:2", "found 2 column(s)", "'1;2'", "at least 3 columns", "e_few.xml:4"});
    writeFile("text.csv", "t;x\n0;1\n1;abc\n");
    expectError("e_text.xml", mvfile("text.csv", 2),
                {d + "text.csv:3", "'abc'", "column 2", "at least 2 columns"});
    writeFile("nan.csv", "0;1\n1;nan\n");
    expectError("e_nan.xml", mvfile("nan.csv", 2),
                {d + "nan.csv:2", "'nan'", "at least 2 columns"});
    writeFile("gap.csv", "0;1\n1;;2\n");
    expectError("e_gap.xml", mvfile("gap.csv", 2), {d + "gap.csv:2", "empty value in column 2"});
    writeFile("time.csv", "0 1\n1 2\n1 3\n");
    expectError("e_time.xml", mvfile("time.csv", 2),
                {d + "time.csv:3", "time 1 ", "line 2", "increase strictly"});
    expectError("e_missing.xml", mvfile("nosuch.csv", 2),
                {d + "e_missing.xml:5", "'" + d + "nosuch.csv'"});
    writeFile("empty.csv", "time;x\n");
    expectError("e_empty.xml", mvfile("empty.csv", 2),
                {d + "empty.csv", "no data rows", d + "e_empty.xml:4"});
    writeFile("rot1.csv", "0\n");
    expectError("e_rot1.xml",
                inObject("    <mvrotfile id=\"1\" duration=\"1\"><file name=\"rot1.csv\"/><axisp1 "
                         "x=\"0\" y=\"0\" z=\"0\"/>"
                         "<axisp2 x=\"0\" y=\"0\" z=\"1\"/></mvrotfile>\n"),
                {d + "rot1.csv:1", "found 1 column(s)", "'0'", "time, angle"});
}

#include <sstream>

#include "case/motion_table.h"

TEST(MotionTable, HeaderOnlyWhenTheFirstLineHasNoNumber) {
    using namespace seaspring::model;
    TableSpec spec;
    spec.name = "data.csv";
    spec.expect = "2 columns: time, value";
    std::istringstream header("time;x\n0;1\n1;2\n");
    const MotionTable t = readTable(header, spec);
    ASSERT_EQ(t.time.size(), 2u);
    EXPECT_EQ(t.value[1].x, 2.0);
    // A first data row with a typo is an error naming the file and line, not a skipped header.
    std::istringstream typo("0;1x\n1;2\n");
    try {
        readTable(typo, spec);
        FAIL() << "expected an error";
    } catch (const seaspring::Error& e) {
        EXPECT_NE(std::string(e.what()).find("data.csv:1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'1x'"), std::string::npos) << e.what();
    }
}
