// SeaSpring — MIT licence.
/// \file blowup_check.cpp
/// \brief Blow-up detection (see blowup_check.h).
#include "solver/blowup_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <omp.h>

#include "core/format.h"
#include "physics/blowup_bounds.h"
#include "physics/time_integration.h"
#include "physics/vcpm.h"

namespace seaspring::solver {

namespace {

constexpr std::size_t kNamedParticles = 5;  ///< particles a diagnosis lists

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.4g", v);
    return b;
}

bool finite3(const physics::Double3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool finite4(const physics::Float4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

/// Particles a state holds per kept scan before the last good state is kept only at every
/// K-th scan (resolveKeepEvery).
constexpr std::size_t kKeepParticles = std::size_t(1) << 18;

/// Keeps the first kNamedParticles offenders and the largest value.
struct Offenders {
    std::vector<BlowupParticle> first;
    std::uint64_t count = 0;
    double worst = 0;
    void add(std::uint32_t id, const physics::Double3& pos, double value) {
        if (first.size() < kNamedParticles) first.push_back({id, pos, value});
        ++count;
        if (!(std::fabs(value) <= std::fabs(worst))) worst = value;  // NaN wins
    }
};

}  // namespace

BlowupCheck::BlowupCheck(const SolverCase& c, const BackendSetup& s, const RunOptions& o)
    : case_(c), setup_(s), opt_(o), every_(o.blowup_check_every),
      keep_every_(resolveKeepEvery(o.blowup_keep_every, c.particles.size())) {
    for (const SolidBody& b : c.solids) outside_.push_back({b.mkbound, 0, 0, 0, -1});
    for (std::uint32_t r = 0; r < s.solid.nsolid; ++r) ++outside_[s.solid.body[r]].particles;
}

std::optional<BlowupDiagnosis> BlowupCheck::afterStep(double t, long long step, double dt,
                                                      std::uint32_t active_fluid, long long dtmin_hits) {
    const SolverParameters& p = case_.params;
    const std::uint32_t nfluid = case_.nfluid;
    if (p.min_fluid_stop > 0 && nfluid > 0 && double(active_fluid) < p.min_fluid_stop * nfluid) {
        BlowupDiagnosis d;
        d.quantity = "fluid loss";
        d.time = t;
        d.step = step;
        d.value = double(active_fluid) / nfluid;
        d.bound = p.min_fluid_stop;
        d.count = nfluid - active_fluid;
        d.message = std::to_string(nfluid - active_fluid) + " of " + std::to_string(nfluid) +
                    " fluid particles excluded: " + std::to_string(active_fluid) + " active is below MinFluidStop " +
                    num(p.min_fluid_stop) + " of the fluid";
        d.likely_option = fluidOption();
        return d;
    }
    streak_ = dtmin_hits > last_hits_ ? streak_ + 1 : 0;
    last_hits_ = dtmin_hits;
    if (streak_ >= physics::kMaxDtMinStreak) {
        BlowupDiagnosis d;
        d.quantity = "dt at DtMin";
        d.time = t;
        d.step = step;
        d.value = double(streak_);
        d.bound = double(physics::kMaxDtMinStreak);
        d.message = "the CFL condition asked for a step below DtMin in " + std::to_string(streak_) +
                    " steps in a row (dt = " + num(dt) + " s): the flow is diverging and DtMin only hides it";
        d.likely_option = fluidOption();
        return d;
    }
    return std::nullopt;
}

BlowupDiagnosis BlowupCheck::nonFiniteStep(double t, long long step, const std::string& what) const {
    BlowupDiagnosis d;
    d.quantity = "non-finite time step";
    d.time = t;
    d.step = step;
    d.value = NAN;
    d.message = what;
    d.likely_option = case_.nfluid > 0 ? fluidOption() : solidOption(0);
    return d;
}

long long resolveKeepEvery(long long requested, std::size_t particles) {
    if (requested > 0) return requested;
    return std::max<long long>(1, (long long)((particles + kKeepParticles - 1) / kKeepParticles));
}

void BlowupCheck::quickScan(const std::vector<physics::Double3>& solid_pos, double t, long long step) {
    last_scan_ = step;
    ++since_keep_;
    countOutside(solid_pos.data(), t);
}

void BlowupCheck::countOutside(const physics::Double3* solid_pos, double t) {
    const SolidSetup& so = setup_.solid;
    std::vector<std::uint32_t> out(outside_.size(), 0);
    for (std::uint32_t r = 0; r < so.nsolid; ++r)
        if (physics::solidOutside(so.keep, solid_pos[r])) ++out[so.body[r]];
    for (std::size_t b = 0; b < outside_.size(); ++b) {
        SolidOutside& o = outside_[b];
        o.outside = out[b];
        if (out[b] > o.most) o.most = out[b];
        if (out[b] > 0 && o.first_time < 0) {
            o.first_time = t;
            warnings_.push_back("warning: solid mkbound=" + std::to_string(o.mkbound) + ": " + std::to_string(out[b]) +
                                " of " + std::to_string(o.particles) + " particles outside the simulation domain (by more than 2h) at t=" +
                                num(t) + " s (counted in run.json; each is frozen where it left, at rest, its bonds broken)");
        }
    }
}

std::optional<BlowupDiagnosis> BlowupCheck::scan(const HostState& st, double t, long long step, double dt) {
    last_scan_ = step;
    since_keep_ = 0;
    const std::size_t np = st.pos.size();
    // Counted on the run's host threads (an integer sum: the same on any number); only a count
    // above zero walks the particles in id order for the first offenders.
    const long long n = static_cast<long long>(np);
    const int threads = opt_.threads > 0 ? opt_.threads : omp_get_max_threads();  // as the CPU backend
    long long nbad = 0;
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : nbad) if (threads > 1)
    for (long long i = 0; i < n; ++i) nbad += physics::particleNotFinite(st.pos[i], st.velrho[i], st.excl[i]) ? 1 : 0;
    Offenders bad;
    if (nbad > 0)
        for (std::size_t i = 0; i < np; ++i)
            if (physics::particleNotFinite(st.pos[i], st.velrho[i], st.excl[i])) bad.add(std::uint32_t(i), st.pos[i], NAN);
    BlowupDiagnosis d;
    d.time = t;
    d.step = step;
    const SolidSetup& so = setup_.solid;
    if (bad.count > 0) {
        bool solid = false;
        for (const BlowupParticle& b : bad.first) solid = solid || (b.id >= so.first_solid && b.id < so.first_solid + so.nsolid);
        d.quantity = "non-finite state";
        d.message = std::to_string(bad.count) + " particle(s) with a non-finite position, velocity or density";
        d.likely_option = solid ? solidOption(dt) : fluidOption();
        d.count = bad.count;
        d.value = NAN;
        d.particles = bad.first;
        return d;
    }
    // Solids: the alarms their sub-steps raised (physics::SolidAlarmKind), and the particles
    // outside the domain.
    constexpr int kKinds = int(physics::kSolidAlarmContactMotion) + 1;
    Offenders alarmed[kKinds];
    double first_time[kKinds] = {};
    if (so.nsolid > 0) countOutside(st.pos.data() + so.first_solid, t);
    for (std::uint32_t r = 0; r < so.nsolid; ++r) {
        const std::uint32_t id = so.first_solid + r;
        const physics::Double3 p = st.pos[id];
        if (r >= st.solid_alarm.size()) continue;
        const physics::SolidAlarm& a = st.solid_alarm[r];
        if (a.kind == physics::kSolidAlarmNone || a.kind >= std::uint32_t(kKinds)) continue;
        Offenders& o = alarmed[a.kind];
        if (o.count == 0 || a.time < first_time[a.kind]) first_time[a.kind] = a.time;
        o.add(id, p, a.value);
    }
    // The kind raised first (on a tie, the lower kind).
    int kind = 0;
    for (int k = 1; k < kKinds; ++k)
        if (alarmed[k].count > 0 && (kind == 0 || first_time[k] < first_time[kind])) kind = k;
    if (kind == 0) return std::nullopt;
    const Offenders& hit = alarmed[kind];
    const physics::ContactParams& cp = so.contact;
    double bound = NAN;
    std::string what;
    switch (kind) {
    case physics::kSolidAlarmNotFinite:
        d.quantity = "non-finite state";
        what = "a non-finite position or velocity";
        break;
    case physics::kSolidAlarmStrain:
        d.quantity = "solid bond strain";
        bound = physics::kMaxBondStrain;
        what = "an intact bond strained to " + num(hit.worst) + " (bound " + num(bound) + ")";
        break;
    case physics::kSolidAlarmSpeed:
        d.quantity = "solid speed";
        bound = so.materials[so.body[hit.first[0].id - so.first_solid]].max_speed;
        what = "a speed of " + num(hit.worst) + " m/s (bound " + num(bound) + " m/s)";
        break;
    case physics::kSolidAlarmContactOverflow:
        d.quantity = "solid contact candidates";
        bound = double(so.contact_cap);
        what = num(hit.worst) + " contact candidates within " + num(cp.list_range) + " m (the list holds " +
               num(bound) + ")";
        break;
    default:
        d.quantity = "solid contact motion";
        bound = 0.5 * (cp.list_range - cp.range);
        what = "a displacement of " + num(hit.worst) + " m in one sub-cycle (bound " + num(bound) +
               " m, half the contact list's margin)";
        break;
    }
    d.count = hit.count;
    d.value = kind == physics::kSolidAlarmNotFinite ? NAN : hit.worst;
    d.bound = bound;
    d.particles = hit.first;
    d.onset = first_time[kind];
    d.message = std::to_string(hit.count) + " VCPM solid particle(s) with " + what + ", first in the sub-step at t=" +
                num(first_time[kind]) + " s";
    d.likely_option = kind == physics::kSolidAlarmContactOverflow
                          ? "VcpmContact (more particles within 1.5 dp of one solid particle than a contact list holds: "
                            "bodies crushed into each other or into a wall)"
                          : solidOption(dt);
    return d;
}

void BlowupCheck::describe(BlowupDiagnosis& d, const HostState& st) const {
    if (!d.particles.empty()) return;
    for (std::size_t i = 0; i < st.pos.size() && d.particles.size() < kNamedParticles; ++i)
        if (!finite3(st.pos[i]) || !finite4(st.velrho[i])) d.particles.push_back({std::uint32_t(i), st.pos[i], NAN});
    if (!d.particles.empty()) return;
    static const char* const kReason[] = {"active", "left the domain", "density out of range", "not finite"};
    std::uint64_t by[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < st.pos.size(); ++i) {
        const std::uint8_t e = st.excl[i];
        if (e == 0 || e > 3) continue;
        ++by[e];
        if (d.particles.size() < kNamedParticles) d.particles.push_back({std::uint32_t(i), st.pos[i], double(e)});
    }
    std::string s;
    for (int e = 1; e <= 3; ++e)
        if (by[e] > 0) s += (s.empty() ? "" : ", ") + std::to_string(by[e]) + " " + kReason[e];
    if (!s.empty()) d.message += " (" + s + ")";
}

std::vector<std::string> BlowupCheck::takeWarnings() {
    std::vector<std::string> w;
    w.swap(warnings_);
    return w;
}

std::string BlowupCheck::solidOption(double dt) const {
    const double limit = setup_.solid.dt;
    const int n = opt_.solid_substeps;
    if (n > 0 && case_.nfluid > 0 && dt / n > limit * (1 + 1e-9))
        return "-vcpmsubsteps:" + std::to_string(n) + " (a solid sub-step dt/N = " + num(dt / n) +
               " s exceeds the stability limit VcpmDtCoef dp/c_S = " + num(limit) + " s; use 0, automatic)";
    if (case_.params.vcpm_dt_coef > 0.8)
        return "VcpmDtCoef (" + num(case_.params.vcpm_dt_coef) + ": stable up to about 0.8 for Poisson's ratio >= 0)";
    return "the solid's material (youngmod, poissratio, density) or VcpmDtCoef (" + num(case_.params.vcpm_dt_coef) +
           ")";
}

std::string BlowupCheck::fluidOption() const {
    const SolverParameters& p = case_.params;
    if (p.dt_fixed > 0)
        return "DtFixed / -dtfixed (" + num(p.dt_fixed) + " s: a fixed step ignores the CFL condition; remove it)";
    if (p.cfl_number > 0.3) return "the CFL number (" + num(p.cfl_number) + "; 0.2 is usual)";
    return "the case's boundaries, Visco (" + num(p.visco) + ") or DensityDT, or a lower CFL number (" +
           num(p.cfl_number) + ")";
}

std::string describeBlowup(const BlowupDiagnosis& d) {
    std::string s = "blow-up detected (" + d.quantity + ") at t=" + num(d.time) + " s, step " + std::to_string(d.step) +
                    ": " + d.message;
    if (!d.particles.empty()) {
        s += "; particles";
        for (const BlowupParticle& p : d.particles)
            s += " " + std::to_string(p.id) + " at (" + num(p.pos.x) + ", " + num(p.pos.y) + ", " + num(p.pos.z) + ")";
        if (d.count > d.particles.size()) s += " ...";
    }
    return s + "; likely cause: " + d.likely_option;
}

}  // namespace seaspring::solver
