// SeaSpring — MIT licence.
/// \file blowup_bounds.h
/// \brief The physical bounds past which a run is declared blown up
///        (solver/blowup_check.h): no stable weakly-compressible SPH or VCPM state reaches them,
///        so a normal run never meets them, while a diverging one passes them within a few steps.
///        The VCPM solid's tests run inside its sub-steps (physics/vcpm.h raises a SolidAlarm).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/host_device.h"
#include "physics/sph_types.h"
#include "physics/time_integration.h"

namespace seaspring::physics {

/// Largest bond strain |l/l0 - 1| of an intact VCPM bond: a bond stretched to twice its rest
/// length (or crushed to nothing) is no elastic state; breakable bonds break long before.
constexpr double kMaxBondStrain = 1.0;

/// Largest speed of a VCPM solid particle [m/s] (VcpmMaterial::max_speed): ten times the
/// faster of the solid's P-wave speed c_S (elastic waves carry particle speeds of
/// strain x c_S < c_S) and the fluid's speed of sound c0 (flows are kept below 0.1 c0), and at
/// least 100 m/s (free fall, 500 m).
inline double solidSpeedBound(double wave_speed, double c0) {
    const double c = wave_speed > c0 ? wave_speed : c0;
    const double b = 10.0 * c;
    return b > 100.0 ? b : 100.0;
}

/// Steps in a row whose dt the CFL condition put below DtMin (raised to DtMin) after which the
/// run is declared blown up: the flow needs ever smaller steps, DtMin only hides it.
constexpr long long kMaxDtMinStreak = 1000;

/// The stretch |l - l0| of a bond past kMaxBondStrain l0 (NaN included); no division, so the
/// sub-step can test every bond it visits.
SEASPRING_HD inline bool bondPastBound(double len, double rest) { return !(fabs(len - rest) <= kMaxBondStrain * rest); }

/// The speed |v| of a solid particle [m/s].
SEASPRING_HD inline double speedOf(const Double3& v) { return sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

/// A speed |v|^2 past bound^2 (NaN included).
SEASPRING_HD inline bool speedPastBound(double vx, double vy, double vz, double bound) {
    return !(vx * vx + vy * vy + vz * vz <= bound * bound);
}

/// A value that is not finite.
SEASPRING_HD inline bool notFinite(double x) { return !(x - x == 0.0); }

/// A particle the state scan rejects (solver/blowup_check.h): a position, velocity or density
/// that is not finite, or fluid excluded for that reason. The host's scan of a downloaded state
/// and the backends' count of such particles (NotFiniteCountPass) both decide with it.
SEASPRING_HD inline bool particleNotFinite(const Double3& p, const Float4& vr, std::uint8_t excl) {
    return notFinite(p.x) || notFinite(p.y) || notFinite(p.z) || notFinite(vr.x) || notFinite(vr.y) ||
           notFinite(vr.z) || notFinite(vr.w) || excl == kExcludedNotFinite;
}

/// Why a VCPM solid particle's alarm was raised (SolidAlarm::kind).
enum SolidAlarmKind : std::uint32_t {
    kSolidAlarmNone = 0,
    kSolidAlarmNotFinite = 1,  ///< a position or velocity component is not finite
    kSolidAlarmStrain = 2,     ///< an intact bond strained past kMaxBondStrain
    kSolidAlarmSpeed = 3,      ///< faster than its material's max_speed
    kSolidAlarmContactOverflow = 4,  ///< more contact candidates than the list holds (solid_contact.h)
    kSolidAlarmContactMotion = 5,    ///< moved more than the contact list's margin allows in one sub-cycle
};

/// The first bound a solid particle passed, raised inside the sub-step that passed it (each
/// particle writes only its own entry; sticky until the run stops), so a blow-up is caught
/// with the sub-step it happened in, whatever the particle does afterwards (leaves the domain
/// and freezes, breaks all its bonds).
struct SolidAlarm {
    double time = 0;   ///< [s] of the evaluation that raised it
    double value = 0;  ///< the strain, the speed [m/s], or NaN
    std::uint32_t kind = kSolidAlarmNone;
    std::uint32_t pad = 0;
};

/// Raises alarm `kind` for particle s unless one is raised already (or `a` is null: a unit
/// test's state without alarms).
SEASPRING_HD inline void raiseSolidAlarm(SolidAlarm* a, std::uint32_t s, std::uint32_t kind, double value, double time) {
    if (!a || a[s].kind != kSolidAlarmNone) return;
    SolidAlarm r;
    r.time = time;
    r.value = value;
    r.kind = kind;
    a[s] = r;
}

}  // namespace seaspring::physics
