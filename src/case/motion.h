// SeaSpring — MIT licence.
/// \file motion.h
/// \brief Prescribed movements of boundary objects (GenCase's `<motion>`): the case model's
///        MotionSet, validated and in SI units (angles in radians, data files embedded).
///
/// gencase reads them from the definition (gencase/motion.h), writes them into the resolved
/// case and the solver reads them back (case/motion_xml.h); the solver's motion player
/// turns them into poses. Ids are integers >= 1; `next` -1 ends the chain; duration -1 =
/// forever; finish +inf = no finish time.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace seaspring::model {

enum class MovementKind { Rect, RectAce, Rot, RotSinu, RectSinu, RectFile, RotFile, Wait, Null };

/// Tabulated motion, time strictly increasing.
/// RectFile: value = displacement x,y,z [m] (columns not given in the file are 0).
/// RotFile: value.x = angle [rad], value.y = value.z = 0.
struct MotionTable {
    std::vector<double> time;
    std::vector<Vec3d> value;
};

/// One movement of a chain. Only the fields of its kind are meaningful; the others are 0.
struct Movement {
    int id = 0;  ///< >= 1, unique within the object
    MovementKind kind = MovementKind::Null;
    double duration = -1;     ///< [s]; -1 = forever (always -1 for Null)
    int next = -1;            ///< id of the following movement; -1 = chain ends
    bool has_velini = false;  ///< RectAce: <velini> given; false = keep previous velocity
    bool has_phase = false;   ///< RotSinu/RectSinu: <phase> given. When false the phase
                              ///< is 0 (DualSPHysics would continue the previous phase)
    Vec3d vel{0, 0, 0};       ///< Rect: velocity [m/s]
    Vec3d velini{0, 0, 0};    ///< RectAce: initial velocity [m/s]
    Vec3d ace{0, 0, 0};       ///< RectAce: acceleration [m/s^2]
    Vec3d freq{0, 0, 0};      ///< RectSinu: frequency per axis [Hz]
    Vec3d ampl{0, 0, 0};      ///< RectSinu: amplitude per axis [m]
    Vec3d phase{0, 0, 0};     ///< RectSinu: phase per axis [rad]
    double ang_vel = 0;       ///< Rot: angular velocity [rad/s]
    double ang_freq = 0;      ///< RotSinu: frequency [Hz]
    double ang_ampl = 0;      ///< RotSinu: amplitude [rad]
    double ang_phase = 0;     ///< RotSinu: phase [rad]
    Vec3d axis_p1{0, 0, 0};   ///< Rot, RotSinu, RotFile: rotation axis from p1 ...
    Vec3d axis_p2{0, 0, 0};   ///< ... to p2 (p1 != p2)
    MotionTable table;        ///< RectFile, RotFile
    std::string source_file;  ///< RectFile, RotFile: resolved path of the data file
    int line = 0;             ///< line of the element in the case XML
};

struct MotionObject {
    int mkbound = 0;         ///< `ref`: the mkbound number (not the global MK)
    int first_movement = 0;  ///< `begin mov`
    double start = 0;        ///< [s], >= 0
    double finish = std::numeric_limits<double>::infinity();  ///< [s], +inf if absent
    std::vector<Movement> movements;                          ///< in file order
    int line = 0;                                             ///< line of <objreal> in the case XML

    /// The movement with this id, or nullptr.
    const Movement* movement(int id) const;
};

struct MotionSet {
    std::vector<MotionObject> objects;  ///< in file order, refs unique

    /// The object whose `ref` is `mkbound`, or nullptr.
    const MotionObject* find(int mkbound) const;
    bool empty() const { return objects.empty(); }
};

}  // namespace seaspring::model
