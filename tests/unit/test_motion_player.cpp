// SeaSpring — MIT licence.
/// \file test_motion_player.cpp
/// \brief Tests of the motion player: every movement kind against closed forms, start/finish,
///        chains, velocity and phase carried along a chain, file tables, DualSPHysics' rotation
///        sense in parsed cases, and the rolling tank of the shared DualSPHysics cases. The rigid
///        transforms and rotation matrices: test_rigid_transform.cpp.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "case/motion.h"
#include "case/xml_source.h"
#include "gencase/motion.h"
#include "solver/motion_player.h"
#include "gencase_test_util.h"
#include "motion_test_util.h"

using namespace seaspring;
using namespace seaspring::solver;
using model::MotionObject;
using model::Movement;
using model::MovementKind;
using namespace seaspring::test::motion;

namespace {

Movement movement(MovementKind kind, int id, double duration, int next = -1) {
    Movement m;
    m.kind = kind;
    m.id = id;
    m.duration = duration;
    m.next = next;
    return m;
}

MotionObject object(std::vector<Movement> movements, double start = 0,
                    double finish = std::numeric_limits<double>::infinity()) {
    MotionObject o;
    o.mkbound = 7;
    o.line = 42;
    o.first_movement = movements.front().id;
    o.start = start;
    o.finish = finish;
    o.movements = std::move(movements);
    return o;
}

Movement rotation(MovementKind kind, int id, double duration, Vec3d p1, Vec3d p2, int next = -1) {
    Movement m = movement(kind, id, duration, next);
    m.axis_p1 = p1;
    m.axis_p2 = p2;
    return m;
}


/// Displacement of the object's origin (the translation part).
Vec3d shift(const RigidTransform& tr) { return {tr.t[0], tr.t[1], tr.t[2]}; }

void expectPureTranslation(const RigidTransform& tr, const Vec3d& d, double tol,
                           const std::string& what) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_EQ(tr.r[i][j], i == j ? 1.0 : 0.0) << what;
    expectNear(shift(tr), d, tol, what);
}

/// Angle of a rotation about an axis along +z (p2 - p1 = +z): DS turns (1,0,0) to
/// (cos a, -sin a, 0) (right-handed about -z).
double angleAboutPlusZ(const RigidTransform& tr) { return std::atan2(-tr.r[1][0], tr.r[0][0]); }
/// Same for an axis along +y: (1,0,0) goes to (cos a, 0, sin a).
double angleAboutPlusY(const RigidTransform& tr) { return std::atan2(tr.r[2][0], tr.r[0][0]); }


std::string scratch() {
    static const std::string dir =
        test::scratchDir("motion_player_" + std::to_string(::getpid()));
    return dir;
}

/// Rows "t, angle[deg]" of a DualSPHysics motion file, read independently of gencase.
std::vector<std::pair<double, double>> readSeries(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::pair<double, double>> rows;
    std::string line;
    while (std::getline(in, line)) {
        for (char& ch : line)
            if (ch == ',' || ch == ';') ch = ' ';
        std::istringstream ls(line);
        double t, a;
        if (ls >> t >> a) rows.emplace_back(t, a);
    }
    return rows;
}

}  // namespace

// ---------------------------------------------------------------- single movements

TEST(MotionPlayer, RectMovesAtConstantVelocityBetweenStartAndFinish) {
    Movement m = movement(MovementKind::Rect, 1, -1);
    m.vel = {1.0, -2.0, 0.5};
    const MotionObject o = object({m}, /*start=*/0.5, /*finish=*/2.0);
    expectPureTranslation(motionTransformAt(o, 0.0), {0, 0, 0}, 0, "t=0");
    expectPureTranslation(motionTransformAt(o, 0.3), {0, 0, 0}, 0, "before start");
    expectPureTranslation(motionTransformAt(o, 0.5), {0, 0, 0}, 0, "at start");
    expectPureTranslation(motionTransformAt(o, 1.0), {0.5, -1.0, 0.25}, kTol, "t=1");
    expectPureTranslation(motionTransformAt(o, 1.75), {1.25, -2.5, 0.625}, kTol, "t=1.75");
    expectPureTranslation(motionTransformAt(o, 2.0), {1.5, -3.0, 0.75}, kTol, "at finish");
    expectPureTranslation(motionTransformAt(o, 9.0), {1.5, -3.0, 0.75}, kTol, "after finish");
}

TEST(MotionPlayer, RectAceWithVeliniFollowsTheQuadratic) {
    Movement m = movement(MovementKind::RectAce, 1, 3.0);
    m.has_velini = true;
    m.velini = {1.0, 0.0, -0.5};
    m.ace = {0.2, -1.0, 0.0};
    const MotionObject o = object({m});
    for (double t : {0.1, 0.7, 1.9, 3.0}) {
        const Vec3d want{1.0 * t + 0.1 * t * t, -0.5 * t * t, -0.5 * t};
        expectPureTranslation(motionTransformAt(o, t), want, kTol, "t=" + std::to_string(t));
    }
    // The chain ends after 3 s: the pose is held.
    expectPureTranslation(motionTransformAt(o, 10), {3.0 + 0.9, -4.5, -1.5}, kTol, "held");
}

TEST(MotionPlayer, RotTurnsAtConstantRateAboutTheGivenAxis) {
    Movement m = rotation(MovementKind::Rot, 1, -1, {1, 2, 0}, {1, 2, 1});
    m.ang_vel = kPi / 2;  // rad/s
    const MotionObject o = object({m}, 1.0);
    expectNear(motionTransformAt(o, 1.0).apply({2, 2, 0}), {2, 2, 0}, 0, "at start");
    expectNear(motionTransformAt(o, 2.0).apply({2, 2, 0}), {1, 1, 0}, kTol, "90 deg");
    expectNear(motionTransformAt(o, 3.0).apply({2, 2, 0}), {0, 2, 0}, kTol, "180 deg");
    const double h = std::sqrt(0.5);
    expectNear(motionTransformAt(o, 1.5).apply({2, 2, 4}), {1 + h, 2 - h, 4}, kTol, "45 deg");
    EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, 1.3)), 0.3 * kPi / 2, kTol);
}

TEST(MotionPlayer, RotSinuAngleIsTheSinusoidMinusItsStartValue) {
    Movement m = rotation(MovementKind::RotSinu, 1, -1, {0, 0, -1}, {0, 0, 2});
    m.ang_ampl = 0.4;
    m.ang_freq = 0.75;
    m.ang_phase = 0.3;
    m.has_phase = true;
    const MotionObject o = object({m});
    for (double t : {0.0, 0.1, 0.45, 0.8, 2.2}) {
        const double want = 0.4 * (std::sin(0.3 + 2 * kPi * 0.75 * t) - std::sin(0.3));
        EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, t)), want, kTol) << "t=" << t;
    }
}

TEST(MotionPlayer, RectSinuMovesEachAxisOnItsOwnSinusoid) {
    Movement m = movement(MovementKind::RectSinu, 1, -1);
    m.ampl = {0.1, 0.0, -0.25};
    m.freq = {2.0, 5.0, 0.5};
    m.phase = {0.0, 1.0, kPi / 2};
    m.has_phase = true;
    const MotionObject o = object({m}, 0.25);
    expectPureTranslation(motionTransformAt(o, 0.25), {0, 0, 0}, 0, "at start");
    for (double t : {0.3, 0.5, 0.9, 1.6}) {
        const double tau = t - 0.25;
        const Vec3d want{0.1 * std::sin(2 * kPi * 2.0 * tau), 0.0,
                         -0.25 * (std::sin(kPi / 2 + 2 * kPi * 0.5 * tau) - 1.0)};
        expectPureTranslation(motionTransformAt(o, t), want, kTol, "t=" + std::to_string(t));
    }
    // A quarter period of z: cos(pi/2 + pi/2) - 1 = -1 -> +0.25 (hand value).
    EXPECT_NEAR(motionTransformAt(o, 0.75).t[2], 0.25, kTol);
}

TEST(MotionPlayer, WaitAndNullDoNotMove) {
    const MotionObject w = object({movement(MovementKind::Wait, 1, 2.0)});
    expectPureTranslation(motionTransformAt(w, 1.0), {0, 0, 0}, 0, "wait");
    const MotionObject n = object({movement(MovementKind::Null, 1, -1)});
    expectPureTranslation(motionTransformAt(n, 1e6), {0, 0, 0}, 0, "null");
}

// ---------------------------------------------------------------- file tables

TEST(MotionPlayer, RectFilePlaysTheTableFromItsFirstRowAsDualSphysicsDoes) {
    // Table starting at t0 = 1 s with a non-zero first row: DS plays it from the first row
    // (time shifted by t0) and moves by (row - first row).
    Movement m = movement(MovementKind::RectFile, 1, -1);
    m.table.time = {1.0, 2.0, 4.0};
    m.table.value = {{0.5, 0, 1}, {1.5, 0, 1}, {1.5, 2, 0}};
    const MotionObject o = object({m}, 0.5);
    expectPureTranslation(motionTransformAt(o, 0.5), {0, 0, 0}, 0, "movement start = row 0");
    expectPureTranslation(motionTransformAt(o, 1.0), {0.5, 0, 0}, kTol, "half way to row 1");
    expectPureTranslation(motionTransformAt(o, 1.5), {1.0, 0, 0}, kTol, "row 1");
    expectPureTranslation(motionTransformAt(o, 2.0), {1.0, 0.5, -0.25}, kTol, "row 1..2");
    expectPureTranslation(motionTransformAt(o, 3.5), {1.0, 2.0, -1.0}, kTol, "row 2");
    expectPureTranslation(motionTransformAt(o, 50), {1.0, 2.0, -1.0}, kTol, "after the table");
    expectPureTranslation(motionTransformAt(o, 0.2), {0, 0, 0}, 0, "before start");
    // So soon after the start that t0 + tau rounds to t0: still the first row.
    expectPureTranslation(motionTransformAt(object({m}), 1e-300), {0, 0, 0}, 0, "tiny tau");
}

TEST(MotionPlayer, RectFileWithASingleRowOrAFiniteDurationHolds) {
    Movement one = movement(MovementKind::RectFile, 1, -1);
    one.table.time = {0.3};
    one.table.value = {{4, 5, 6}};
    expectPureTranslation(motionTransformAt(object({one}), 2.0), {0, 0, 0}, 0, "one row");
    Movement m = movement(MovementKind::RectFile, 1, 0.5);
    m.table.time = {0.0, 1.0};
    m.table.value = {{0, 0, 0}, {0, 0, 2}};
    expectPureTranslation(motionTransformAt(object({m}), 3.0), {0, 0, 1}, kTol, "cut at 0.5 s");
}

TEST(MotionPlayer, RotFileAngleIsInterpolatedRelativeToTheFirstRow) {
    Movement m = rotation(MovementKind::RotFile, 1, -1, {0, 0, 0}, {0, 0, 1});
    m.table.time = {0.0, 1.0, 3.0};
    m.table.value = {{0.1, 0, 0}, {0.5, 0, 0}, {-0.3, 0, 0}};
    const MotionObject o = object({m});
    EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, 0.0)), 0.0, 0);
    EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, 0.25)), 0.1, kTol);
    EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, 1.0)), 0.4, kTol);
    EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, 2.0)), 0.0, kTol);
    EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, 2.5)), -0.2, kTol);
    EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, 7.0)), -0.4, kTol);
}

// ---------------------------------------------------------------- chains

TEST(MotionPlayer, ChainRectWaitRotRotatesAboutTheAxisAsGivenNotAsMoved) {
    Movement a = movement(MovementKind::Rect, 1, 1.0, 2);
    a.vel = {2, 0, 0};
    const Movement b = movement(MovementKind::Wait, 2, 0.5, 3);
    Movement c = rotation(MovementKind::Rot, 3, -1, {0, 0, 0}, {0, 0, 1});
    c.ang_vel = kPi / 2;
    const MotionObject o = object({a, b, c}, 0.25);
    const Vec3d x0{1, 0, 3};
    expectNear(motionTransformAt(o, 0.75).apply(x0), {2, 0, 3}, kTol, "rect half way");
    expectNear(motionTransformAt(o, 1.25).apply(x0), {3, 0, 3}, kTol, "rect done");
    expectNear(motionTransformAt(o, 1.6).apply(x0), {3, 0, 3}, kTol, "waiting");
    expectNear(motionTransformAt(o, 1.75).apply(x0), {3, 0, 3}, kTol, "rot begins");
    // 90 deg about the z axis through the ORIGIN (not through the moved object): (3,0) -> (0,-3).
    expectNear(motionTransformAt(o, 2.75).apply(x0), {0, -3, 3}, kTol, "rot 90 deg");
    expectNear(motionTransformAt(o, 3.75).apply(x0), {-3, 0, 3}, kTol, "rot 180 deg");
}

TEST(MotionPlayer, RectAceWithoutVeliniTakesTheVelocityAtTheEndOfThePreviousMovement) {
    Movement a = movement(MovementKind::Rect, 1, 1.0, 2);
    a.vel = {2, 0, 0};
    Movement b = movement(MovementKind::RectAce, 2, 2.0, 3);  // no velini: v0 = 2
    b.ace = {1, 0, 0};
    Movement c = movement(MovementKind::RectAce, 3, -1);  // no velini: v0 = 2 + 1*2 = 4
    c.ace = {-3, 0, 0};
    const MotionObject o = object({a, b, c});
    EXPECT_NEAR(motionTransformAt(o, 1.0).t[0], 2.0, kTol);
    EXPECT_NEAR(motionTransformAt(o, 2.0).t[0], 2.0 + 2.0 + 0.5, kTol);
    EXPECT_NEAR(motionTransformAt(o, 3.0).t[0], 8.0, kTol);
    EXPECT_NEAR(motionTransformAt(o, 4.0).t[0], 8.0 + 4.0 - 1.5, kTol);
    // The velocity is continuous at both joints: one-sided differences on either side agree
    // to |a| h (a jump of the velocity would be >= 2 here).
    const double h = 1e-4;
    const auto x = [&](double t) { return motionTransformAt(o, t).t[0]; };
    for (double tj : {1.0, 3.0})
        EXPECT_NEAR((x(tj) - x(tj - h)) / h, (x(tj + h) - x(tj)) / h, 1e-3) << "joint " << tj;
    // After a wait the previous velocity is 0 (DS resets it for every other kind).
    Movement a2 = a;
    a2.next = 4;
    const Movement w = movement(MovementKind::Wait, 4, 1.0, 5);
    Movement d = movement(MovementKind::RectAce, 5, -1);
    d.ace = {0, 0, 2};
    const MotionObject o2 = object({a2, w, d});
    EXPECT_NEAR(motionTransformAt(o2, 3.0).t[2], 1.0, kTol);
    EXPECT_NEAR(motionTransformAt(o2, 3.0).t[0], 2.0, kTol);
}

TEST(MotionPlayer, RectAceAsFirstMovementWithoutVeliniStartsAtRest) {
    Movement m = movement(MovementKind::RectAce, 1, -1);
    m.ace = {0, 4, 0};
    expectPureTranslation(motionTransformAt(object({m}), 1.5), {0, 4.5, 0}, kTol, "from rest");
}

TEST(MotionPlayer, SinusoidWithoutPhaseContinuesThePreviousSinusoidOfTheSameKind) {
    // DS (JMotionMovActive::NextMov, PhasePrev): phase = previous phase + 2 pi f dur.
    Movement a = movement(MovementKind::RectSinu, 1, 0.3, 2);
    a.ampl = {0.2, 0.0, 0.1};
    a.freq = {1.0, 1.0, 2.0};
    a.phase = {0.5, 0.7, 0.0};
    a.has_phase = true;
    Movement b = movement(MovementKind::RectSinu, 2, -1);  // no <phase>
    b.ampl = {0.3, 0.4, 0.1};
    b.freq = {2.0, 1.0, 1.0};
    const MotionObject o = object({a, b});
    const Vec3d phi{0.5 + 2 * kPi * 1.0 * 0.3, 0.7 /* amplitude 0: not advanced */,
                    0.0 + 2 * kPi * 2.0 * 0.3};
    const Vec3d at_joint = shift(motionTransformAt(o, 0.3));
    const Vec3d want_joint{0.2 * (std::sin(phi.x) - std::sin(0.5)), 0.0,
                           0.1 * std::sin(phi.z)};
    expectNear(at_joint, want_joint, kTol, "end of the first");
    const double tau = 0.45;
    const auto sinu = [&](double a, double f, double p) {
        return a * (std::sin(p + 2 * kPi * f * tau) - std::sin(p));
    };
    const Vec3d want{want_joint.x + sinu(0.3, 2.0, phi.x), sinu(0.4, 1.0, phi.y),
                     want_joint.z + sinu(0.1, 1.0, phi.z)};
    expectNear(shift(motionTransformAt(o, 0.3 + tau)), want, kTol, "second, continued phase");

    // With <phase> given the second starts from it.
    Movement b2 = b;
    b2.has_phase = true;
    b2.phase = {0, 0, 0};
    const MotionObject o2 = object({a, b2});
    const Vec3d want2{want_joint.x + 0.3 * std::sin(2 * kPi * 2.0 * tau),
                      0.4 * std::sin(2 * kPi * tau), want_joint.z + 0.1 * std::sin(2 * kPi * tau)};
    expectNear(shift(motionTransformAt(o2, 0.3 + tau)), want2, kTol, "second, own phase");

    // After another kind the phase restarts at 0.
    Movement r = movement(MovementKind::Rect, 1, 0.3, 2);
    const MotionObject o3 = object({r, b});
    const Vec3d want3{0.3 * std::sin(2 * kPi * 2.0 * tau), 0.4 * std::sin(2 * kPi * tau),
                      0.1 * std::sin(2 * kPi * tau)};
    expectNear(shift(motionTransformAt(o3, 0.3 + tau)), want3, kTol, "after mvrect");
}

TEST(MotionPlayer, RotSinuWithoutPhaseContinuesThePreviousRotSinu) {
    Movement a = rotation(MovementKind::RotSinu, 1, 0.2, {0, 0, 0}, {0, 0, 1}, 2);
    a.ang_ampl = 0.5;
    a.ang_freq = 1.5;
    a.ang_phase = 0.1;
    a.has_phase = true;
    Movement b = rotation(MovementKind::RotSinu, 2, -1, {0, 0, 0}, {0, 0, 1});
    b.ang_ampl = 0.25;
    b.ang_freq = 3.0;
    const MotionObject o = object({a, b});
    const double phi = 0.1 + 2 * kPi * 1.5 * 0.2;
    const double first = 0.5 * (std::sin(phi) - std::sin(0.1));
    const double tau = 0.13;
    const double want = first + 0.25 * (std::sin(phi + 2 * kPi * 3.0 * tau) - std::sin(phi));
    EXPECT_NEAR(angleAboutPlusZ(motionTransformAt(o, 0.2 + tau)), want, kTol);
}

TEST(MotionPlayer, AChainThatEndsHoldsItsLastPoseAndFinishCutsTheChain) {
    Movement a = movement(MovementKind::Rect, 1, 1.0, 2);
    a.vel = {1, 0, 0};
    Movement b = rotation(MovementKind::Rot, 2, 2.0, {0, 0, 0}, {0, 0, 1});
    b.ang_vel = kPi / 4;
    const MotionObject o = object({a, b});
    // Ends at t = 3 after 90 deg: (x0 + (1,0,0)) turned by 90 deg.
    expectNear(motionTransformAt(o, 3.0).apply({0, 0, 0}), {0, -1, 0}, kTol, "end");
    expectNear(motionTransformAt(o, 30.0).apply({0, 0, 0}), {0, -1, 0}, kTol, "held");
    // finish = 2 (inside the rotation, after 45 deg).
    const MotionObject cut = object({a, b}, 0.0, 2.0);
    const double h = std::sqrt(0.5);
    expectNear(motionTransformAt(cut, 2.0).apply({0, 0, 0}), {h, -h, 0}, kTol, "at finish");
    expectNear(motionTransformAt(cut, 2.5).apply({0, 0, 0}), {h, -h, 0}, kTol, "after finish");
    // A movement of duration 0 is skipped.
    Movement z = movement(MovementKind::Rect, 3, 0.0, 1);
    z.vel = {100, 100, 100};
    MotionObject zo = object({z, a, b});
    expectNear(motionTransformAt(zo, 0.5).apply({0, 0, 0}), {0.5, 0, 0}, kTol, "zero duration");
}

TEST(MotionPlayer, ALoopingChainRepeatsItsPeriod) {
    Movement a = movement(MovementKind::Rect, 1, 1.0, 2);
    a.vel = {1, 0, 0};
    Movement b = movement(MovementKind::Rect, 2, 1.0, 1);
    b.vel = {-1, 0, 0};
    const MotionObject o = object({a, b});
    EXPECT_NEAR(motionTransformAt(o, 10.5).t[0], 0.5, 1e-12);
    EXPECT_NEAR(motionTransformAt(o, 11.25).t[0], 0.75, 1e-12);
    EXPECT_NEAR(motionTransformAt(o, 1001.75).t[0], 0.25, 1e-9);
}

TEST(MotionPlayer, ALoopOfZeroDurationIsReportedInsteadOfHanging) {
    const Movement a = movement(MovementKind::Wait, 1, 0.0, 2);
    const Movement b = movement(MovementKind::Wait, 2, 0.0, 1);
    try {
        motionTransformAt(object({a, b}), 1.0);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("line 42"), std::string::npos) << msg;
        EXPECT_NE(msg.find("ref=7"), std::string::npos) << msg;
        EXPECT_NE(msg.find("zero total duration"), std::string::npos) << msg;
    }
    // Before the start nothing is evaluated.
    EXPECT_NO_THROW(motionTransformAt(object({a, b}, 2.0), 1.0));
}

TEST(MotionPlayer, IsAPureFunctionOfTime) {
    Movement a = movement(MovementKind::RectAce, 1, 0.7, 2);
    a.ace = {1, 2, 3};
    Movement b = rotation(MovementKind::RotSinu, 2, 1.1, {1, 0, 0}, {1, 1, 1}, 3);
    b.ang_ampl = 0.3;
    b.ang_freq = 2;
    Movement c = movement(MovementKind::RectAce, 3, -1);
    c.ace = {0, 0, -1};
    const MotionObject o = object({a, b, c}, 0.1);
    const std::vector<double> times{2.5, 0.3, 1.4, 0.9, 3.3, 1.4, 0.05};
    std::vector<RigidTransform> first;
    for (double t : times) first.push_back(motionTransformAt(o, t));
    for (std::size_t i = times.size(); i-- > 0;) {
        const RigidTransform again = motionTransformAt(o, times[i]);
        for (int r = 0; r < 3; ++r) {
            EXPECT_EQ(again.t[r], first[i].t[r]);
            for (int k = 0; k < 3; ++k) EXPECT_EQ(again.r[r][k], first[i].r[r][k]);
        }
    }
}

// ---------------------------------------------------------------- parsed cases

TEST(MotionPlayer, ParsedMvrotInDegreesUsesTheDualSphysicsSense) {
    const std::string path = test::writeFile(scratch(), "rot.xml", R"(<motion>
  <objreal ref="3">
    <begin mov="1" start="0.5"/>
    <mvrot id="1" duration="-1">
      <vel ang="90"/> <axisp1 x="0" y="0" z="0"/> <axisp2 x="0" y="0" z="1"/>
    </mvrot>
  </objreal>
</motion>)");
    const model::XmlSource src(path);
    const model::MotionSet set = gencase::parseMotion(src, src.root(), {});
    ASSERT_EQ(set.objects.size(), 1u);
    // 90 deg/s for 1 s: (1,0,0) -> (0,-1,0).
    expectNear(motionTransformAt(set.objects[0], 1.5).apply({1, 0, 0}), {0, -1, 0}, kTol, "90");
}

TEST(MotionPlayer, RollingTankDeepFollowsItsAngleSeries) {
    const std::string dir = std::string(SEASPRING_SHARED_DIR) + "/dualsphysics-cases/flexstruc/";
    if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << dir << " is missing";
    const gencase::GeneratedCase g = test::buildCase(dir + "CaseRollingTankDeep_Def.xml");
    const MotionObject* tank = g.motion.find(0);
    ASSERT_NE(tank, nullptr);
    const auto rows = readSeries(dir + "RollingTankDeepTimeSeries.csv");
    ASSERT_EQ(rows.size(), 499u);
    const double deg = kPi / 180.0;
    const double t0 = rows.front().first;  // 0.011045..., angle 0.0194 deg
    // DS plays the series from its first row: at simulation time t_k - t0 the tank has turned
    // by (angle_k - angle_0) about the axis (0.3045, *, 0), p2 - p1 = +y.
    for (std::size_t k : {0u, 1u, 7u, 100u, 250u, 251u, 497u, 498u}) {
        const double t = rows[k].first - t0;
        const RigidTransform tr = motionTransformAt(*tank, t);
        const double want = (rows[k].second - rows.front().second) * deg;
        EXPECT_NEAR(angleAboutPlusY(tr), want, 1e-11) << "row " << k << " t=" << t;
        EXPECT_NEAR(tr.r[1][1], 1.0, 1e-15);  // a rotation about y
        expectNear(tr.apply({0.3045, 0.5, 0}), {0.3045, 0.5, 0}, 1e-14, "axis point");
    }
    // Between rows 100 and 101: linear interpolation of the angle.
    const double tm = 0.5 * (rows[100].first + rows[101].first) - t0;
    const double want_mid = (0.5 * (rows[100].second + rows[101].second) - rows[0].second) * deg;
    EXPECT_NEAR(angleAboutPlusY(motionTransformAt(*tank, tm)), want_mid, 1e-11);
    // After the series (duration 100 s) the last angle is held.
    const double last = (rows.back().second - rows.front().second) * deg;
    EXPECT_NEAR(angleAboutPlusY(motionTransformAt(*tank, 20.0)), last, 1e-11);
    // A positive angle lifts the +x end (DS sense); angle > 0 early in the series.
    ASSERT_GT(rows[10].second, rows[0].second);
    const RigidTransform early = motionTransformAt(*tank, rows[10].first - t0);
    EXPECT_GT(early.apply({0.609, 0, 0}).z, 0.0);
    // The plate (mvnull) never moves.
    const MotionObject* plate = g.motion.find(1);
    ASSERT_NE(plate, nullptr);
    expectPureTranslation(motionTransformAt(*plate, 3.0), {0, 0, 0}, 0, "mvnull");
}
