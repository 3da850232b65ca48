// SeaSpring — MIT licence.
/// \file motion.h
/// \brief The GenCase `<motion>` section of the case definition: prescribed movements of
///        boundary objects, parsed from DualSPHysics syntax and validated.
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
/// The result is the case model's MotionSet (case/motion.h); the resolved case holds it in
/// the normalized form of case/motion_xml.h.
#pragma once

#include <pugixml.hpp>

#include "case/motion.h"
#include "case/xml_source.h"
#include "gencase/expression.h"

namespace seaspring::gencase {

using model::MotionObject;
using model::MotionSet;
using model::MotionTable;
using model::Movement;
using model::MovementKind;
using model::XmlSource;

/// Parses and validates a DualSPHysics `<motion>` element of the case `src`; numeric
/// attributes may be expressions ("#...") evaluated with `ev`. Motion data files are read
/// and embedded. Throws seaspring::Error "file:line: ..." on any problem.
MotionSet parseMotion(const XmlSource& src, pugi::xml_node motion_node,
                      const ExpressionEvaluator& ev);

}  // namespace seaspring::gencase
