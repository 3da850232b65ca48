// SeaSpring — MIT licence.
/// \file blowup_bounds.h
/// \brief Host only. The physical bounds past which a run is declared blown up
///        (solver/blowup_check.h): no stable weakly-compressible SPH or VCPM state reaches them,
///        so a normal run never meets them, while a diverging one passes them within a few steps.
#pragma once

#include <cmath>

namespace seaspring::physics {

/// Largest bond strain |l/l0 - 1| of an intact VCPM bond: a bond stretched to twice its rest
/// length (or crushed to nothing) is no elastic state; breakable bonds break long before.
constexpr double kMaxBondStrain = 1.0;

/// Largest speed of a VCPM solid particle [m/s]: ten times the faster of the solid's P-wave
/// speed c_S (elastic waves carry particle speeds of strain x c_S < c_S) and the fluid's speed of
/// sound c0 (flows are kept below 0.1 c0), and at least 100 m/s (free fall, 500 m).
inline double solidSpeedBound(double wave_speed, double c0) {
    const double c = wave_speed > c0 ? wave_speed : c0;
    const double b = 10.0 * c;
    return b > 100.0 ? b : 100.0;
}

/// Steps in a row whose dt the CFL condition put below DtMin (raised to DtMin) after which the
/// run is declared blown up: the flow needs ever smaller steps, DtMin only hides it.
constexpr long long kMaxDtMinStreak = 1000;


}  // namespace seaspring::physics
