// SeaSpring — MIT licence.
/// \file step_dt.h
/// \brief A step's dt from a force evaluation's maxima: the variable dt (variableDt), checked
///        finite and raised to DtMin, then the fixed dt when the case gives one, and with solids
///        the number of solid sub-steps and their length. The host (solver/step_context.cpp) and
///        a one-thread device pass (the Verlet step launched without waiting for its dt,
///        solver/engine.h) both use this, in double, with the same bits.
#pragma once

#include <cstdint>

#include "core/host_device.h"
#include "physics/time_integration.h"
#include "physics/vcpm.h"

namespace seaspring::physics {

/// What a step's dt is made from (the case's constants and parameters).
struct DtRule {
    double h = 0, cs0 = 0, cfl = 0;
    double dt_min = 0;        ///< minimumDt's value
    double dt_fixed = 0;      ///< DtFixed (> 0: the step's dt whatever the forces say)
    double solid_dt = 0;      ///< the solids' sub-step bound (0: no solids)
    int solid_substeps = 0;   ///< -vcpmsubsteps (0: solidSubsteps decides)
};

/// The variable dt of one evaluation: not finite (`bad`, the run stops as a blow-up and nothing
/// integrates), raised to DtMin (`raised`), or as computed.
struct LimitedDt {
    double dt = 0;
    std::uint32_t raised = 0, bad = 0;
};

SEASPRING_HD inline LimitedDt limitedVariableDt(const DtMaxima& m, const DtRule& r) {
    LimitedDt l;
    l.dt = variableDt(m, r.h, r.cs0, r.cfl);
    // Finite: a NaN fails dt == dt, an infinity gives NaN for dt - dt.
    l.bad = (l.dt == l.dt && l.dt - l.dt == 0.0) ? 0u : 1u;
    if (l.bad == 0u && l.dt < r.dt_min) {
        l.dt = r.dt_min;
        l.raised = 1u;
    }
    return l;
}

/// A Verlet step's dt and its solid sub-cycle.
struct StepDt {
    double dt = 0;            ///< the fluid step
    double dt_solid = 0;      ///< the solid sub-step, dt / omega (with solids)
    double span = 0;          ///< the sub-cycle's length, dt_solid omega (SolidState::span)
    double variable = 0;      ///< the evaluation's variable dt (limitedVariableDt)
    std::int32_t omega = 0;   ///< solid sub-steps (0 without solids)
    std::uint32_t raised = 0; ///< the variable dt was raised to DtMin
    std::uint32_t bad = 0;    ///< the variable dt is not finite: a gate word (nothing integrates)
    std::uint32_t pad = 0;
};

SEASPRING_HD inline StepDt verletStepDt(const DtMaxima& m, const DtRule& r) {
    const LimitedDt l = limitedVariableDt(m, r);
    StepDt s;
    s.variable = l.dt;
    s.raised = l.raised;
    s.bad = l.bad;
    s.dt = r.dt_fixed > 0 ? r.dt_fixed : l.dt;
    if (r.solid_dt > 0 && l.bad == 0u) {
        s.omega = r.solid_substeps > 0 ? r.solid_substeps : solidSubsteps(s.dt, r.solid_dt);
        s.dt_solid = s.dt / double(s.omega);
        s.span = s.dt_solid * double(s.omega);
    }
    return s;
}

}  // namespace seaspring::physics
