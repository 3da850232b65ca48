// SeaSpring — MIT licence.
/// \file time_integration.h
/// \brief Per-particle updates of the symplectic (predictor/corrector) and Verlet schemes,
///        the DBC boundary density update and the exclusion checks; and the variable dt.
///
/// Formulas as DualSPHysics 5.4 (dualsphysics-conventions.md §5), all updates in double and
/// stored as float (velocity, density) or double (position). a = acceleration from the force
/// evaluation (without gravity), ar = d(rho)/dt. Fluid:
///   symplectic predictor (dth = dt/2): rho = rho^n + dth ar; v = v^n + dth (a + g);
///       x = x^n + dth v^n.
///   corrector: eps = -(ar/rho^{n+1/2}) dt; rho = rho^n (2 - eps)/(2 + eps);
///       v = v^n + dt (a + g); x = x^{n+1/2} + dt/2 v^{n+1}, which is DualSPHysics'
///       x^n + dt/2 (v^n + v^{n+1}) up to rounding (in double) without keeping x^n: 24 bytes
///       per particle less (docs/performance-large.md).
///   Verlet: rho = rho^{n-1} + 2dt ar; v = v^{n-1} + 2dt (a+g); x = x^n + dt v^n + dt^2/2 (a+g);
///       every VerletSteps-th step Euler: rho = rho^n + dt ar; v = v^n + dt (a+g).
/// Boundary (DBC) particles: density by the same formula, then rho = max(rho, rho0).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/host_device.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// Why a particle left the simulation (stored per particle; 0 = active).
enum ExclusionReason : std::uint8_t {
    kActive = 0,
    kExcludedPosition = 1,  ///< left the simulation domain
    kExcludedDensity = 2,   ///< density outside [RhopOutMin, RhopOutMax]
    kExcludedNotFinite = 3, ///< position, velocity or density not finite
};

struct StepConstants {
    double gx = 0, gy = 0, gz = 0;              ///< gravity [m/s^2]
    double minx = 0, miny = 0, minz = 0;        ///< simulation domain
    double maxx = 0, maxy = 0, maxz = 0;
    float rhop0 = 1000;                         ///< DBC clamp
    float rhop_out_min = 700, rhop_out_max = 1300;
};

/// The exclusion test applied after every fluid update.
SEASPRING_HD inline std::uint8_t exclusionOf(const Double3& p, const Float4& v, const StepConstants& s) {
    const bool finite = p.x == p.x && p.y == p.y && p.z == p.z && v.x == v.x && v.y == v.y &&
                        v.z == v.z && v.w == v.w && p.x - p.x == 0.0 && p.y - p.y == 0.0 &&
                        p.z - p.z == 0.0;
    if (!finite) return kExcludedNotFinite;
    if (p.x < s.minx || p.y < s.miny || p.z < s.minz || p.x > s.maxx || p.y > s.maxy || p.z > s.maxz)
        return kExcludedPosition;
    if (v.w < s.rhop_out_min || v.w > s.rhop_out_max) return kExcludedDensity;
    return kActive;
}

/// DBC density: never below rho0.
SEASPRING_HD inline float clampBoundaryDensity(float rho, float rhop0) { return rho < rhop0 ? rhop0 : rho; }

/// Symplectic predictor of a fluid particle from its state at the start of the step.
SEASPRING_HD inline void symplecticPredictFluid(const Double3& pos0, const Float4& vr0, const Float4& acear,
                                                double dt, const StepConstants& s, Double3& pos, Float4& vr) {
    const double dth = 0.5 * dt;
    vr.w = float(double(vr0.w) + dth * double(acear.w));
    vr.x = float(double(vr0.x) + dth * (double(acear.x) + s.gx));
    vr.y = float(double(vr0.y) + dth * (double(acear.y) + s.gy));
    vr.z = float(double(vr0.z) + dth * (double(acear.z) + s.gz));
    pos.x = pos0.x + dth * double(vr0.x);
    pos.y = pos0.y + dth * double(vr0.y);
    pos.z = pos0.z + dth * double(vr0.z);
}

/// Symplectic corrector of a fluid particle from the predictor's position `pos_half` and
/// density `rho_half` and the step-start velocity and density `vr0`.
SEASPRING_HD inline void symplecticCorrectFluid(const Double3& pos_half, const Float4& vr0, float rho_half,
                                                const Float4& acear, double dt, const StepConstants& s,
                                                Double3& pos, Float4& vr) {
    const double eps = (-double(acear.w) / double(rho_half)) * dt;
    vr.w = float(double(vr0.w) * ((2.0 - eps) / (2.0 + eps)));
    const double vx = double(vr0.x) + dt * (double(acear.x) + s.gx);
    const double vy = double(vr0.y) + dt * (double(acear.y) + s.gy);
    const double vz = double(vr0.z) + dt * (double(acear.z) + s.gz);
    vr.x = float(vx);
    vr.y = float(vy);
    vr.z = float(vz);
    const double dth = 0.5 * dt;
    pos.x = pos_half.x + dth * vx;
    pos.y = pos_half.y + dth * vy;
    pos.z = pos_half.z + dth * vz;
}

/// Symplectic density of a boundary particle (predictor: `rho_half` unused, corrector: used).
SEASPRING_HD inline float symplecticPredictBoundRho(float rho0_step, float ar, double dt, float rhop0) {
    return clampBoundaryDensity(float(double(rho0_step) + 0.5 * dt * double(ar)), rhop0);
}
SEASPRING_HD inline float symplecticCorrectBoundRho(float rho0_step, float rho_half, float ar, double dt,
                                                    float rhop0) {
    const double eps = (-double(ar) / double(rho_half)) * dt;
    return clampBoundaryDensity(float(double(rho0_step) * ((2.0 - eps) / (2.0 + eps))), rhop0);
}

/// Verlet update of a fluid particle. `vr` is the state at n, `vrm1` at n-1 (for the Euler
/// step pass euler = true: then vrm1 is not used). Writes the state at n+1.
SEASPRING_HD inline void verletFluid(const Double3& pos_n, const Float4& vr, const Float4& vrm1,
                                     const Float4& acear, double dt, bool euler, const StepConstants& s,
                                     Double3& pos, Float4& out) {
    const double ax = double(acear.x) + s.gx, ay = double(acear.y) + s.gy, az = double(acear.z) + s.gz;
    const double dt205 = 0.5 * dt * dt;
    pos.x = pos_n.x + (double(vr.x) * dt + ax * dt205);
    pos.y = pos_n.y + (double(vr.y) * dt + ay * dt205);
    pos.z = pos_n.z + (double(vr.z) * dt + az * dt205);
    if (euler) {
        out.x = float(double(vr.x) + ax * dt);
        out.y = float(double(vr.y) + ay * dt);
        out.z = float(double(vr.z) + az * dt);
        out.w = float(double(vr.w) + dt * double(acear.w));
    } else {
        const double dt2 = dt + dt;
        out.x = float(double(vrm1.x) + ax * dt2);
        out.y = float(double(vrm1.y) + ay * dt2);
        out.z = float(double(vrm1.z) + az * dt2);
        out.w = float(double(vrm1.w) + dt2 * double(acear.w));
    }
}

/// Verlet density of a boundary particle.
SEASPRING_HD inline float verletBoundRho(float rho, float rhom1, float ar, double dt, bool euler, float rhop0) {
    const double r = euler ? double(rho) + dt * double(ar) : double(rhom1) + (dt + dt) * double(ar);
    return clampBoundaryDensity(float(r), rhop0);
}

/// Maxima that decide the variable time step (all exact under any reduction order; a NaN
/// anywhere makes the maximum NaN whatever the order, so a diverged force evaluation gives a
/// non-finite dt on every backend: blow-up detection within the step, solver/blowup_check.h).
struct DtMaxima {
    float ace2 = 0;  ///< max |a|^2 over fluid particles
    float vel2 = 0;  ///< max |v|^2 over fluid particles
    float visc = 0;  ///< max v.r/(r^2+eta2) over all pairs
};

/// The larger of a and b, NaN when either is (maxf keeps a NaN only in its first argument, which
/// would make the result depend on the reduction order).
SEASPRING_HD inline float maxKeepNaN(float a, float b) { return a != a ? a : (b != b ? b : maxf(a, b)); }

SEASPRING_HD inline DtMaxima combineDtMaxima(const DtMaxima& a, const DtMaxima& b) {
    return {maxKeepNaN(a.ace2, b.ace2), maxKeepNaN(a.vel2, b.vel2), maxKeepNaN(a.visc, b.visc)};
}

/// Host only. dt = CFL min( sqrt(h/|a|max), h / (max(c0, 10 |v|max) + h viscmax) ) (host, double; sqrt
/// is correctly rounded everywhere). Returns +inf parts as needed when maxima are zero; a NaN
/// maximum gives a NaN dt (the step then stops as a blow-up).
inline double variableDt(const DtMaxima& m, double h, double cs0, double cfl) {
    const double acemax = std::sqrt(double(m.ace2));
    const double velmax = std::sqrt(double(m.vel2));
    const double dt1 = acemax > 0 ? std::sqrt(h / acemax) : (acemax == 0 ? 1e300 : acemax);  // NaN stays NaN
    const double cv = cs0 > 10.0 * velmax ? cs0 : 10.0 * velmax;
    const double dt2 = h / (cv + h * double(m.visc));
    return cfl * (dt1 < dt2 || dt1 != dt1 ? dt1 : dt2);  // a NaN in either stays NaN
}

/// Host only. The smallest dt a step may take (DualSPHysics' DtMin): `dt_min` when set (> 0),
/// else CoefDtMin h / c0. A variable dt below it is raised to it (and counted).
inline double minimumDt(double dt_min, double coef_dt_min, double h, double cs0) {
    return dt_min > 0 ? dt_min : coef_dt_min * h / cs0;
}

/// Host only. The first step's dt (DualSPHysics' DtIni): `dt_ini` when set (> 0), else h / c0.
inline double initialDt(double dt_ini, double h, double cs0) { return dt_ini > 0 ? dt_ini : h / cs0; }

}  // namespace seaspring::physics
