// SeaSpring — MIT licence.
/// \file motion.cpp
/// \brief The definition's <motion>: the case model's reader in its definition syntax.
#include "gencase/motion.h"

#include "case/motion_xml.h"

namespace seaspring::gencase {

MotionSet parseMotion(const XmlSource& src, pugi::xml_node motion_node,
                      const ExpressionEvaluator& ev) {
    return model::readMotionElement(src, motion_node, ev, model::MotionSyntax::Definition);
}

}  // namespace seaspring::gencase
