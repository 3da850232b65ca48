// SeaSpring — MIT licence.
/// \file motion_xml.h
/// \brief The `<motion>` section in XML: one reader for GenCase's definition syntax and for
///        the normalized form of the resolved case, and the writer of the normalized form.
///
/// Normalized form (writeMotion/readMotion): same element names (canonical ones), every
/// attribute explicit (next="0" = none, finish="-1" = none, anglesunits="radians"),
/// attribute `line` = line of the element in the original case XML, file movements carry
/// `source` (resolved data file path) and a `<table rows columns>` child whose text rows
/// are "t x y z" (mvrectfile) or "t angle" (mvrotfile), numbers as %.17g.
/// <velini> and <phase> are written only when they were given (their absence has meaning).
/// The definition syntax is described in gencase/motion.h (gencase::parseMotion).
#pragma once

#include <pugixml.hpp>

#include "case/motion.h"
#include "case/xml_source.h"

namespace seaspring::model {

/// Which syntax a `<motion>` element is written in.
enum class MotionSyntax {
    Definition,  ///< DualSPHysics' (CASE_Def.xml): aliases, angle units, data files
    Normalized   ///< writeMotion's (the resolved case)
};

/// Reads and validates a `<motion>` element; numeric attributes may be expressions ("#...")
/// evaluated with `ev`. Definition: motion data files are read and embedded. Throws
/// seaspring::Error "file:line: ..." on any problem.
MotionSet readMotionElement(const XmlSource& src, pugi::xml_node motion_node, const ValueEvaluator& ev,
                            MotionSyntax syntax);

/// Appends `<motion>` in the normalized form (see file comment) to `parent`.
void writeMotion(const MotionSet& set, pugi::xml_node parent);

/// Reads a `<motion>` written by writeMotion (exact round trip, including `line`).
MotionSet readMotion(const XmlSource& src, pugi::xml_node motion_node);

}  // namespace seaspring::model
