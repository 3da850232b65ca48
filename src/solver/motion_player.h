// SeaSpring — MIT licence.
/// \file motion_player.h
/// \brief Prescribed boundary motion as a pure function of time: the rigid transform of a
///        motion object (model::MotionObject) at time t relative to its pose at t = 0.
///
/// The result depends on `time` only (no state carried between calls) and uses closed forms
/// for every analytic movement, so the solver can ask for any instant in any order, e.g. the
/// poses at t and t + dt to get the boundary velocity. Host only (std::sin/std::cos in double);
/// the solver copies the matrices to the device, so both backends move boundaries identically.
///
/// Conventions. "DS" = DualSPHysics src/source/JMotionObj.cpp (JMotionObj::ProcesTime,
/// JMotionMovActive::NextMov, ::ConfigData, ::DfConfig, ::DfGetNewPos/DfGetNewAng) and
/// src/source/JMatrix4.h (MatrixRot, MatrixRotZ), read in DualSPHysics/DualSPHysics. tau is
/// the time since the current movement began.
/// - Timing (DS): nothing moves before `obj.start`; from `obj.finish` on the object keeps its
///   pose at finish. The chain runs from `first_movement`, each movement for its `duration`;
///   when a chain ends (`next` = -1) the object holds its last pose. A movement of duration 0
///   is skipped. A chain may loop back to an earlier movement (periodic motion); the loop is
///   replayed movement by movement, so the cost grows with time / (period of the loop).
/// - duration -1 = forever. This follows SeaSpring's case format (docs/case-format.md); DS
///   itself treats a negative duration as an instantaneous "flash" movement of |duration|
///   seconds (JMotionMovActive::Flash), which SeaSpring does not reproduce.
/// - Composition (DS): every movement acts on the current pose in absolute coordinates. A
///   rotation axis is the given points p1, p2 and is NOT carried along by earlier movements
///   (DS moves an object's axes only by its parent's motion; SeaSpring has no nested
///   objects). Pose after movements A then B: x -> B(A(x)).
/// - Rotation sign (DS, JMatrix4::MatrixRot): a positive angle turns right-handed about
///   p1 - p2, i.e. clockwise seen from p2 looking towards p1. Example: p1 = origin,
///   p2 = (0,0,1), +90 deg maps (1,0,0) to (0,-1,0). DS states it in JMatrix4.h:
///   MatrixRotZ(ang), the standard right-handed matrix, equals MatrixRot(ang, 0, (0,0,-1)).
///   For the usual 2D axis p2 - p1 = +y a positive angle lifts +x towards +z.
/// - mvrect: displacement = vel * tau.
/// - mvrectace: displacement = v0 tau + ace tau^2 / 2; v0 = velini when given, else (DS
///   NextMov, `VelPrev`) the velocity at the end of the previous movement of the chain:
///   vel of an mvrect, v0 + ace * duration of an mvrectace, 0 after any other kind and 0 for
///   the first movement of the chain.
/// - mvrot: angle = ang_vel * tau.
/// - mvrectsinu (per axis) and mvrotsinu: A (sin(phi + 2 pi f tau) - sin(phi)) (DS: the
///   position A sin(phase) with the phase advanced by 2 pi f dt each step), so the motion
///   starts from the current pose without a jump. phi = the given <phase>; without <phase>
///   (has_phase false) DS continues the phase of the previous movement when it is of the same
///   kind (mvrectsinu after mvrectsinu, mvrotsinu after mvrotsinu): phi = phi_prev +
///   2 pi f_prev duration_prev (for mvrectsinu only on axes whose previous amplitude is not
///   0, as DS advances only those); otherwise phi = 0. The player does the same (gencase's
///   motion.h and docs/case-format.md describe the absent phase as 0, which holds only
///   when the previous movement is not the same sinusoid).
/// - mvrectfile (DS DfConfig/DfGetNewPos): the table is played from its first row: the
///   displacement at tau is table(t0 + tau) - table(t0), t0 = the first row's time, with
///   linear interpolation between rows and the last row's value held after the table ends.
///   The file's values are thus positions relative to its first row, and its time axis is
///   shifted so that its first row falls on the start of the movement.
/// - mvrotfile: angle at tau = angle(t0 + tau) - angle(t0), interpolated the same way, about
///   the axis p1, p2 with the rotation sign above. Angles are already radians (gencase).
/// - wait, mvnull: no motion (mvnull lasts forever).
#pragma once

#include <vector>

#include "core/vec3.h"
#include "case/motion.h"
#include "physics/particle_updates.h"

namespace seaspring::solver {

/// A rigid transform x -> R x + t (plain data, row-major R).
struct RigidTransform {
    double r[3][3];
    double t[3];

    static RigidTransform identity();
    /// R x0 + t.
    Vec3d apply(const Vec3d& x0) const;
};

/// `first` then `second`: x -> second.apply(first.apply(x)).
RigidTransform compose(const RigidTransform& first, const RigidTransform& second);

/// DS rotation by `angle` [rad] about the axis through p1 and p2 (sign: see file comment);
/// p1 stays fixed. Requires p1 != p2.
RigidTransform axisRotation(const Vec3d& p1, const Vec3d& p2, double angle);

/// The transform of `obj` at `time` [s] relative to its configuration at time 0 (before any
/// motion): x(time) = R x0 + t for every particle of the object, x0 its position at time 0.
/// Throws seaspring::Error (naming the object's line) for a chain that loops through
/// movements of zero total duration, which never advances in time.
RigidTransform motionTransformAt(const model::MotionObject& obj, double time);

/// Every motion object's pose at `time` and at `time + interval`, as the backends take them
/// (physics::RigidMotionGpu: velocity over the interval from the two poses).
std::vector<physics::RigidMotionGpu> motionPosesOver(const model::MotionSet& set, double time, double interval);

}  // namespace seaspring::solver
