// SeaSpring — MIT licence.
/// \file motion_player.cpp
/// \brief Closed-form poses of prescribed boundary motion (conventions in motion_player.h).
#include "solver/motion_player.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "core/error.h"

namespace seaspring::solver {

using model::MotionObject;
using model::MotionTable;
using model::Movement;
using model::MovementKind;

namespace {

const double kTwoPi = 6.283185307179586476925286766559;

RigidTransform translation(const Vec3d& d) {
    RigidTransform tr = RigidTransform::identity();
    tr.t[0] = d.x;
    tr.t[1] = d.y;
    tr.t[2] = d.z;
    return tr;
}

/// A (sin(phase + 2 pi f tau) - sin(phase)): sinusoidal displacement or angle from the start.
double sinusoid(double ampl, double freq, double phase, double tau) {
    return ampl * (std::sin(phase + kTwoPi * freq * tau) - std::sin(phase));
}

/// Row values at time `t`: linear between rows, the first/last row outside the table
/// (DS DfGetNewPos/DfGetNewAng).
Vec3d tableValue(const MotionTable& table, double t) {
    const auto& times = table.time;
    const std::size_t k =
        std::size_t(std::lower_bound(times.begin(), times.end(), t) - times.begin());
    if (k == times.size()) return table.value.back();
    if (k == 0) return table.value.front();
    const double f = (t - times[k - 1]) / (times[k] - times[k - 1]);
    const Vec3d a = table.value[k - 1], b = table.value[k];
    return {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), a.z + f * (b.z - a.z)};
}

/// Table value at tau after the movement began, relative to the first row (DS plays the
/// table from its first row: DfLastPos/DfLastAng start at row 0, time shifted by times[0]).
Vec3d tableDisplacement(const MotionTable& table, double tau) {
    if (table.time.empty()) return {0, 0, 0};
    return tableValue(table, table.time.front() + tau) - table.value.front();
}

/// State carried from one movement of the chain to the next (DS JMotionMovActive: Vel,
/// Phase, PhaseUni after ConfigData/NextMov).
struct ChainState {
    Vec3d vel{0, 0, 0};        ///< velocity at the end of the movement (mvrect, mvrectace)
    Vec3d rect_phase{0, 0, 0};  ///< phase at the end of an mvrectsinu
    double rot_phase = 0;      ///< phase at the end of an mvrotsinu
    MovementKind kind = MovementKind::Null;
    bool any = false;          ///< false before the first movement
};

/// Initial phase of a sinusoidal movement: the given one, or the previous movement's final
/// phase when it was of the same kind and <phase> is absent (DS `PhasePrev`), else 0.
Vec3d rectPhase(const Movement& m, const ChainState& prev) {
    if (m.has_phase) return m.phase;
    if (prev.any && prev.kind == MovementKind::RectSinu) return prev.rect_phase;
    return {0, 0, 0};
}
double rotPhase(const Movement& m, const ChainState& prev) {
    if (m.has_phase) return m.ang_phase;
    if (prev.any && prev.kind == MovementKind::RotSinu) return prev.rot_phase;
    return 0;
}

/// DS advances a mvrectsinu phase only on axes with a non-zero amplitude.
double advancedPhase(double phase, double ampl, double freq, double dur) {
    return ampl != 0 ? phase + kTwoPi * freq * dur : phase;
}

/// The transform of movement `m` after `tau` seconds of it, given the state left by the
/// previous movement; `end` receives the state at the end of the whole movement (used only
/// when the chain goes on, so `m.duration` is then finite).
RigidTransform movementTransform(const Movement& m, double tau, const ChainState& prev,
                                 ChainState& end) {
    end = ChainState{};
    end.kind = m.kind;
    end.any = true;
    const double dur = m.duration;
    switch (m.kind) {
        case MovementKind::Rect:
            end.vel = m.vel;
            return translation(tau * m.vel);
        case MovementKind::RectAce: {
            const Vec3d v0 = m.has_velini ? m.velini : prev.vel;
            end.vel = v0 + dur * m.ace;
            return translation(tau * v0 + (0.5 * tau * tau) * m.ace);
        }
        case MovementKind::Rot:
            return axisRotation(m.axis_p1, m.axis_p2, m.ang_vel * tau);
        case MovementKind::RotSinu: {
            const double phi = rotPhase(m, prev);
            end.rot_phase = phi + kTwoPi * m.ang_freq * dur;
            return axisRotation(m.axis_p1, m.axis_p2,
                                sinusoid(m.ang_ampl, m.ang_freq, phi, tau));
        }
        case MovementKind::RectSinu: {
            const Vec3d phi = rectPhase(m, prev);
            end.rect_phase = {advancedPhase(phi.x, m.ampl.x, m.freq.x, dur),
                              advancedPhase(phi.y, m.ampl.y, m.freq.y, dur),
                              advancedPhase(phi.z, m.ampl.z, m.freq.z, dur)};
            return translation({sinusoid(m.ampl.x, m.freq.x, phi.x, tau),
                                sinusoid(m.ampl.y, m.freq.y, phi.y, tau),
                                sinusoid(m.ampl.z, m.freq.z, phi.z, tau)});
        }
        case MovementKind::RectFile:
            return translation(tableDisplacement(m.table, tau));
        case MovementKind::RotFile:
            return axisRotation(m.axis_p1, m.axis_p2, tableDisplacement(m.table, tau).x);
        case MovementKind::Wait:
        case MovementKind::Null:
            break;
    }
    return RigidTransform::identity();
}

[[noreturn]] void throwZeroLoop(const MotionObject& obj, int id) {
    throw Error("line " + std::to_string(obj.line) + ": <motion> object ref=" +
                std::to_string(obj.mkbound) + ": the chain loops back to movement id=" +
                std::to_string(id) +
                " through movements of zero total duration, so time never advances");
}

}  // namespace

RigidTransform RigidTransform::identity() {
    RigidTransform tr;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) tr.r[i][j] = i == j ? 1.0 : 0.0;
        tr.t[i] = 0.0;
    }
    return tr;
}

Vec3d RigidTransform::apply(const Vec3d& x0) const {
    return {r[0][0] * x0.x + r[0][1] * x0.y + r[0][2] * x0.z + t[0],
            r[1][0] * x0.x + r[1][1] * x0.y + r[1][2] * x0.z + t[1],
            r[2][0] * x0.x + r[2][1] * x0.y + r[2][2] * x0.z + t[2]};
}

RigidTransform compose(const RigidTransform& first, const RigidTransform& second) {
    RigidTransform c;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            c.r[i][j] = second.r[i][0] * first.r[0][j] + second.r[i][1] * first.r[1][j] +
                        second.r[i][2] * first.r[2][j];
        }
        c.t[i] = second.r[i][0] * first.t[0] + second.r[i][1] * first.t[1] +
                 second.r[i][2] * first.t[2] + second.t[i];
    }
    return c;
}

RigidTransform axisRotation(const Vec3d& p1, const Vec3d& p2, double angle) {
    // Right-handed rotation (Rodrigues) about u = (p1 - p2) / |p1 - p2|: the DS sign.
    const Vec3d d = p1 - p2;
    const double n = std::sqrt(dot(d, d));
    SEASPRING_CHECK(n > 0, "rotation axis with p1 == p2");
    const Vec3d u = (1.0 / n) * d;
    const double c = std::cos(angle), s = std::sin(angle), k = 1.0 - c;
    RigidTransform tr;
    tr.r[0][0] = c + u.x * u.x * k;
    tr.r[0][1] = u.x * u.y * k - u.z * s;
    tr.r[0][2] = u.x * u.z * k + u.y * s;
    tr.r[1][0] = u.y * u.x * k + u.z * s;
    tr.r[1][1] = c + u.y * u.y * k;
    tr.r[1][2] = u.y * u.z * k - u.x * s;
    tr.r[2][0] = u.z * u.x * k - u.y * s;
    tr.r[2][1] = u.z * u.y * k + u.x * s;
    tr.r[2][2] = c + u.z * u.z * k;
    // Keep the axis fixed: t = p1 - R p1.
    for (int i = 0; i < 3; ++i) tr.t[i] = 0.0;
    const Vec3d rp1 = tr.apply(p1);
    tr.t[0] = p1.x - rp1.x;
    tr.t[1] = p1.y - rp1.y;
    tr.t[2] = p1.z - rp1.z;
    return tr;
}

RigidTransform motionTransformAt(const MotionObject& obj, double time) {
    RigidTransform pose = RigidTransform::identity();
    if (!(time > obj.start)) return pose;
    const double elapsed = std::min(time, obj.finish) - obj.start;  // time the chain runs
    const double forever = std::numeric_limits<double>::infinity();

    ChainState state;       // left by the previous movement
    double begin = 0;       // start of the current movement, relative to obj.start
    std::size_t idle = 0;   // movements visited since time last advanced
    int id = obj.first_movement;
    while (id > 0) {
        const Movement* m = obj.movement(id);
        SEASPRING_CHECK(m, "motion object ref=", obj.mkbound, " has no movement id=", id);
        const double dur = m->duration < 0 ? forever : m->duration;
        const double left = elapsed - begin;  // >= 0
        ChainState end;
        pose = compose(pose, movementTransform(*m, std::min(left, dur), state, end));
        if (left <= dur || m->next <= 0) break;  // time ends in this movement, or the chain does
        if (dur > 0) {
            idle = 0;
        } else if (++idle > obj.movements.size()) {
            throwZeroLoop(obj, m->next);
        }
        begin += dur;
        state = end;
        id = m->next;
    }
    return pose;
}

std::vector<physics::RigidMotionGpu> motionPosesOver(const model::MotionSet& set, double time, double interval) {
    std::vector<physics::RigidMotionGpu> m(set.objects.size());
    for (std::size_t o = 0; o < m.size(); ++o) {
        const RigidTransform a = motionTransformAt(set.objects[o], time);
        const RigidTransform b = motionTransformAt(set.objects[o], time + interval);
        for (int r = 0; r < 3; ++r) {
            for (int col = 0; col < 3; ++col) {
                m[o].r[3 * r + col] = a.r[r][col];
                m[o].r_next[3 * r + col] = b.r[r][col];
            }
            m[o].t[r] = a.t[r];
            m[o].t_next[r] = b.t[r];
        }
        m[o].inv_dt = 1.0 / interval;
    }
    return m;
}

}  // namespace seaspring::solver
