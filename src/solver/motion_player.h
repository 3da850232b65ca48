// SeaSpring — MIT licence.
/// \file motion_player.h
/// \brief Prescribed boundary motion as a pure function of time: the rigid transform of a
///        motion object (gencase::MotionObject) at time t relative to its pose at t = 0.
///
/// Conventions (documented for users in docs/solver.md):
/// - Nothing moves before `start`; after `finish` the object keeps its pose at finish.
/// - The chain runs from `first_movement`, each movement for its `duration` (-1: forever);
///   when a chain ends the object holds its last pose.
/// - Movements compose in absolute coordinates: rotation axes are the given points p1 -> p2
///   (not moved by earlier movements); positive angles turn right-handed about p2 - p1.
/// - mvrect: x = v tau. mvrectace: x = v0 tau + a tau^2/2, v0 = velini or (without <velini>)
///   the velocity at the end of the previous movement. mvrot: angle = w tau.
/// - mvrectsinu / mvrotsinu: A (sin(2 pi f tau + phi) - sin(phi)), continuous at tau = 0.
/// - mvrectfile: displacement = the table interpolated linearly at tau (held before the first
///   and after the last row). mvrotfile: angle = the table value at tau.
/// (tau = time since the movement began.) Host only; the solver sends the matrices to the
/// device, so both backends move boundaries identically.
#pragma once

#include "core/vec3.h"
#include "gencase/motion.h"

namespace seaspring::solver {

/// x(t) = R x0 + t.
struct RigidTransform {
    double r[3][3];
    double t[3];
    static RigidTransform identity();
    Vec3d apply(const Vec3d& x0) const;
};

/// a then b (b applied after a).
RigidTransform compose(const RigidTransform& a, const RigidTransform& b);

/// The pose of `obj` at `time` relative to t = 0.
RigidTransform motionTransformAt(const gencase::MotionObject& obj, double time);

}  // namespace seaspring::solver
