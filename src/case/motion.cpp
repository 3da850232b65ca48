// SeaSpring — MIT licence.
/// \file motion.cpp
#include "case/motion.h"

namespace seaspring::model {

const Movement* MotionObject::movement(int id) const {
    for (const Movement& m : movements)
        if (m.id == id) return &m;
    return nullptr;
}

const MotionObject* MotionSet::find(int mkbound) const {
    for (const MotionObject& o : objects)
        if (o.mkbound == mkbound) return &o;
    return nullptr;
}

}  // namespace seaspring::model
