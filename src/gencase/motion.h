// SeaSpring — MIT licence.
/// \file motion.h
/// \brief The GenCase `<motion>` section: prescribed movements of boundary objects, parsed
///        from DualSPHysics syntax, validated, and written/read in a self-contained form.
///
/// Input (DualSPHysics syntax, see docs of GenCase):
///   <motion> <objreal ref="MKBOUND"> <begin mov start [finish]/> movements... </objreal>
/// Movements: mvrect, mvrectace, mvrot, mvrotsinu, mvrectsinu (alias mvsinu), mvrectfile
/// (aliases mvfile, mvpredef), mvrotfile, wait, mvnull. Nested <obj> groups, mvcir*,
/// mvrotace, mvrotadvfile and mvpathfile are rejected ("not supported by SeaSpring").
/// Ids are integers >= 1; `next` absent or 0 ends the chain (DualSPHysics convention);
/// duration -1 = forever; finish absent or -1 = no finish time.
/// Angles are given in `anglesunits` (degrees by default) and stored in radians; this
/// covers mvrot vel, mvrotsinu ampl/phase, mvrectsinu phase and mvrotfile angles.
/// Motion files: relative to the case XML's directory; columns separated by ';' ',' tabs or
/// spaces; blank lines and lines starting with '#' are skipped; a first line that is not all
/// numbers is a header; one trailing ';' or ',' per row is accepted.
///
/// Normalized form (writeMotion/readMotion): same element names (canonical ones), every
/// attribute explicit (next="0" = none, finish="-1" = none, anglesunits="radians"),
/// attribute `line` = line of the element in the original case XML, file movements carry
/// `source` (resolved data file path) and a `<table rows columns>` child whose text rows
/// are "t x y z" (mvrectfile) or "t angle" (mvrotfile), numbers as %.17g.
/// <velini> and <phase> are written only when they were given (their absence has meaning).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "core/vec3.h"
#include "gencase/expression.h"
#include "gencase/xml_source.h"

namespace seaspring::gencase {

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

/// Parses and validates a DualSPHysics `<motion>` element of the case `src`; numeric
/// attributes may be expressions ("#...") evaluated with `ev`. Motion data files are read
/// and embedded. Throws seaspring::Error "file:line: ..." on any problem.
MotionSet parseMotion(const XmlSource& src, pugi::xml_node motion_node,
                      const ExpressionEvaluator& ev);

/// Appends `<motion>` in the normalized form (see file comment) to `parent`.
void writeMotion(const MotionSet& set, pugi::xml_node parent);

/// Reads a `<motion>` written by writeMotion (exact round trip, including `line`).
MotionSet readMotion(const XmlSource& src, pugi::xml_node motion_node);

}  // namespace seaspring::gencase
