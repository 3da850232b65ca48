// SeaSpring — MIT licence.
/// \file run_limits.cpp
/// \brief Memory and sub-step limits checked before a run (see run_limits.h).
#include "solver/run_limits.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "core/format.h"
#include "core/memory_budget.h"
#include "physics/vcpm.h"

namespace seaspring::solver {

double loadedCaseBytes(const SolverCase& c) {
    const ParticleSet& p = c.particles;
    const auto bytes = [](const auto& v) { return double(v.size()) * double(sizeof(v[0])); };
    return bytes(p.id) + bytes(p.type) + bytes(p.mk) + bytes(p.pos) + bytes(p.vel) + bytes(p.rhop) + bytes(p.mass) +
           bytes(p.normal);
}

void checkRunMemory(const SolverCase& c, bool gpu) {
    // The case's arrays are in memory already (MemAvailable no longer counts them).
    const double total = double(c.particles.size()) * (gpu ? kRunBytesPerParticleGpu : kRunBytesPerParticle);
    const double more = std::max(0.0, total - loadedCaseBytes(c));
    checkMemory(c.h5_path, 0,
                "the run (" + std::to_string(c.particles.size()) + " particles) beyond its case as read", more,
                "generate the case with a larger dp");
}

void checkSolidSubstep(const SolverCase& c, const SolidSetup& s) {
    if (s.empty()) return;
    const double tmax = c.params.time_max;
    // The body that sets the sub-step: the one with the smallest VcpmDtCoef dp / c_S.
    const SolidBody* worst = nullptr;
    double dt = 0;
    for (const SolidBody& b : c.solids) {
        const physics::VcpmElastic el = physics::vcpmElastic(b.youngmod, b.poissratio, b.density);
        const double d = physics::vcpmTimeStep(c.params.vcpm_dt_coef, c.constants.dp, el.wave_speed);
        if (!worst || d < dt) worst = &b, dt = d;
    }
    if (!worst) return;
    char what[200];
    std::snprintf(what, sizeof what, "youngmod=%g, density=%g: the VCPM sub-step VcpmDtCoef dp/c_S is %.3g s", worst->youngmod,
                  worst->density, s.dt);
    if (!(tmax / s.dt <= kMaxSolidSubsteps))
        throwInputError(c.xml_path, worst->line,
                        std::string("<solid mkbound=\"") + std::to_string(worst->mkbound) + "\"> " + what + ", so TimeMax " +
                            shortText(tmax) + " s needs " + shortText(tmax / s.dt, 3) + " sub-steps (at most " +
                            shortText(kMaxSolidSubsteps) + "); check youngmod (Pa) and density (kg/m^3)");
    const double step = c.params.dt_fixed > 0 && c.params.dt_fixed < s.dt ? c.params.dt_fixed : s.dt;
    if (c.nfluid == 0 && !(step <= tmax))
        throwInputError(c.xml_path, worst->line,
                        std::string("<solid mkbound=\"") + std::to_string(worst->mkbound) + "\"> " + what +
                            ", longer than TimeMax " + shortText(tmax) +
                            " s: the solid would not move; check youngmod (Pa) and density (kg/m^3)");
}

}  // namespace seaspring::solver
