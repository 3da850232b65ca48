// SeaSpring — MIT licence.
/// \file eos_tait.h
/// \brief Tait (Monaghan) equation of state, p = B[(rho/rho0)^gamma - 1], and its inverse for
///        hydrostatic initial conditions.
#pragma once

#include <cmath>

#include "core/host_device.h"

namespace seaspring::physics {

/// B = c0^2 rho0 / gamma [Pa] (DualSPHysics' `b`), from the reference sound speed c0 [m/s].
SEASPRING_HD inline double taitB(double c0, double rho0, double gamma) {
    return c0 * c0 * rho0 / gamma;
}

/// Tait pressure with gamma = 7 [Pa], evaluated in float by repeated products (bit-identical on
/// every backend): p = B ((rho/rho0)^7 - 1); `ovrho0` = 1/rho0.
SEASPRING_HD inline float taitPressure7(float rho, float b, float ovrho0) {
    const float x = rho * ovrho0;
    const float x2 = x * x;
    const float x3 = x2 * x;
    return b * ((x3 * x3 * x) - 1.f);
}

/// Density [kg/m^3] at which the Tait pressure equals rho0*g*depth (hydrostatic column of
/// `depth` metres under gravity magnitude g): rho = rho0 (1 + rho0 g depth / B)^(1/gamma).
/// Used for initial conditions only (library pow: not part of the bit-identical step).
inline double hydrostaticDensity(double rho0, double b, double gamma, double g, double depth) {
    return rho0 * std::pow(1.0 + rho0 * g * depth / b, 1.0 / gamma);
}

}  // namespace seaspring::physics
