// SeaSpring — MIT licence.
/// \file motion_player.cpp
#include "solver/motion_player.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace seaspring::solver {

using gencase::MotionObject;
using gencase::Movement;
using gencase::MovementKind;

namespace {

const double kTwoPi = 6.283185307179586476925;

RigidTransform translation(const Vec3d& d) {
    RigidTransform t = RigidTransform::identity();
    t.t[0] = d.x;
    t.t[1] = d.y;
    t.t[2] = d.z;
    return t;
}

/// Rotation by `angle` about the axis through p1 along p2 - p1 (right-handed).
RigidTransform rotation(const Vec3d& p1, const Vec3d& p2, double angle) {
    Vec3d u = p2 - p1;
    const double n = std::sqrt(dot(u, u));
    u = (1.0 / n) * u;
    const double c = std::cos(angle), s = std::sin(angle), k = 1.0 - c;
    RigidTransform t;
    t.r[0][0] = c + u.x * u.x * k;
    t.r[0][1] = u.x * u.y * k - u.z * s;
    t.r[0][2] = u.x * u.z * k + u.y * s;
    t.r[1][0] = u.y * u.x * k + u.z * s;
    t.r[1][1] = c + u.y * u.y * k;
    t.r[1][2] = u.y * u.z * k - u.x * s;
    t.r[2][0] = u.z * u.x * k - u.y * s;
    t.r[2][1] = u.z * u.y * k + u.x * s;
    t.r[2][2] = c + u.z * u.z * k;
    // Keep p1 fixed: t = p1 - R p1.
    for (int i = 0; i < 3; ++i) t.t[i] = 0;
    const Vec3d rp = t.apply(p1);
    t.t[0] = p1.x - rp.x;
    t.t[1] = p1.y - rp.y;
    t.t[2] = p1.z - rp.z;
    return t;
}

/// Linear interpolation of a table column set at time tau (held outside the table).
Vec3d tableAt(const gencase::MotionTable& tab, double tau) {
    const auto& tt = tab.time;
    if (tt.empty()) return {0, 0, 0};
    if (tau <= tt.front()) return tab.value.front();
    if (tau >= tt.back()) return tab.value.back();
    const std::size_t k = std::size_t(std::upper_bound(tt.begin(), tt.end(), tau) - tt.begin());
    const double f = (tau - tt[k - 1]) / (tt[k] - tt[k - 1]);
    const Vec3d a = tab.value[k - 1], b = tab.value[k];
    return {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), a.z + f * (b.z - a.z)};
}

double sinusoid(double ampl, double freq, double phase, double tau) {
    return ampl * (std::sin(kTwoPi * freq * tau + phase) - std::sin(phase));
}

}  // namespace

RigidTransform RigidTransform::identity() {
    RigidTransform t;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) t.r[i][j] = i == j ? 1.0 : 0.0;
        t.t[i] = 0;
    }
    return t;
}

Vec3d RigidTransform::apply(const Vec3d& x) const {
    return {r[0][0] * x.x + r[0][1] * x.y + r[0][2] * x.z + t[0],
            r[1][0] * x.x + r[1][1] * x.y + r[1][2] * x.z + t[1],
            r[2][0] * x.x + r[2][1] * x.y + r[2][2] * x.z + t[2]};
}

RigidTransform compose(const RigidTransform& a, const RigidTransform& b) {
    RigidTransform c;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) c.r[i][j] = b.r[i][0] * a.r[0][j] + b.r[i][1] * a.r[1][j] + b.r[i][2] * a.r[2][j];
        c.t[i] = b.r[i][0] * a.t[0] + b.r[i][1] * a.t[1] + b.r[i][2] * a.t[2] + b.t[i];
    }
    return c;
}

RigidTransform motionTransformAt(const MotionObject& obj, double time) {
    RigidTransform pose = RigidTransform::identity();
    if (!(time > obj.start)) return pose;
    const double te = std::min(time, obj.finish) - obj.start;
    double tau0 = 0;                // start of the current movement (since obj.start)
    Vec3d vel{0, 0, 0};             // velocity at the end of the previous movement
    int id = obj.first_movement;
    for (int guard = 0; guard < 1000000 && id > 0; ++guard) {
        const Movement* m = obj.movement(id);
        if (!m) break;
        const double dur = m->duration < 0 ? std::numeric_limits<double>::infinity() : m->duration;
        const double tau = std::min(te - tau0, dur);
        if (tau <= 0 && dur > 0) break;
        RigidTransform step = RigidTransform::identity();
        Vec3d vend{0, 0, 0};
        switch (m->kind) {
            case MovementKind::Rect:
                step = translation(tau * m->vel);
                vend = m->vel;
                break;
            case MovementKind::RectAce: {
                const Vec3d v0 = m->has_velini ? m->velini : vel;
                step = translation(tau * v0 + (0.5 * tau * tau) * m->ace);
                vend = v0 + tau * m->ace;
                break;
            }
            case MovementKind::Rot:
                step = rotation(m->axis_p1, m->axis_p2, m->ang_vel * tau);
                break;
            case MovementKind::RotSinu:
                step = rotation(m->axis_p1, m->axis_p2, sinusoid(m->ang_ampl, m->ang_freq, m->ang_phase, tau));
                break;
            case MovementKind::RectSinu:
                step = translation({sinusoid(m->ampl.x, m->freq.x, m->phase.x, tau),
                                    sinusoid(m->ampl.y, m->freq.y, m->phase.y, tau),
                                    sinusoid(m->ampl.z, m->freq.z, m->phase.z, tau)});
                break;
            case MovementKind::RectFile:
                step = translation(tableAt(m->table, tau));
                break;
            case MovementKind::RotFile:
                step = rotation(m->axis_p1, m->axis_p2, tableAt(m->table, tau).x);
                break;
            case MovementKind::Wait:
            case MovementKind::Null:
                break;
        }
        pose = compose(pose, step);
        vel = vend;
        if (tau < dur) break;  // time ends inside this movement
        tau0 += dur;
        id = m->next;
    }
    return pose;
}

}  // namespace seaspring::solver
