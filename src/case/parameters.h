// SeaSpring — MIT licence.
/// \file parameters.h
/// \brief `<parameters>` of the resolved case: every key of core/case_parameters.h with its
///        value (defaults filled in by gencase), read into SolverParameters, and the
///        `<simulationdomain>` box.
///
/// readSolverParameters is strict: unknown, repeated or deprecated keys, a missing required
/// key and any value seaspring does not implement stop with "FILE:LINE: <parameter>
/// key=\"K\" value=\"V\": ... is not supported by seaspring (supported: ...)". Keys that have
/// no effect in the chosen configuration (SlipMode, MDbcThreshold and NoPenetration with DBC, ShiftCoef and
/// ShiftTFS without shifting) are checked to be numbers and otherwise ignored, as
/// DualSPHysics does.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <pugixml.hpp>

#include "case/xml_source.h"
#include "core/vec3.h"

namespace seaspring::model {

/// `<parameters>` as the solver uses them (DualSPHysics meaning and defaults).
struct SolverParameters {
    int boundary = 1;           ///< 1 DBC, 2 mDBC
    int slip_mode = 1;          ///< mDBC: 1 DBC vel=0, 2 no-slip, 3 free-slip
    double mdbc_threshold = 0;  ///< mDBC SlipMode 1: kernel sum below which rho = rho0
    int step_algorithm = 1;   ///< 1 Verlet, 2 symplectic
    int verlet_steps = 40;    ///< Verlet: an Euler step every this many steps
    int kernel = 2;           ///< 1 cubic spline, 2 Wendland C2
    int visco_treatment = 1;  ///< 1 artificial, 2 laminar+SPS, 3 laminar
    double visco = 0;         ///< artificial alpha, or kinematic viscosity nu [m^2/s]
    double visco_bound_factor = 1;
    /// LaminarLatticeCorrection (SeaSpring): 1 divides out the laminar term's bias on the particle
    /// lattice (physics::laminarLatticeRatio: nu x 1.0153 in 2D, x 1.0115 in 3D at h = 2 dp);
    /// 0 keeps DualSPHysics' operator.
    int laminar_lattice_correction = 1;
    int density_dt = 0;  ///< 0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full
    double density_dt_value = 0.1;
    double coef_dt_min = 0.05;  ///< DtMin = CoefDtMin*h/c0 when dt_min is 0
    double dt_ini = 0;          ///< [s]; 0: h/c0
    double dt_min = 0;          ///< [s]; 0: CoefDtMin*h/c0
    double dt_fixed = 0;        ///< [s]; 0: variable time step
    bool dt_all_particles = false;
    double time_max = 0, time_out = 0;               ///< [s]
    double rhop_out_min = 700, rhop_out_max = 1300;  ///< [kg/m^3]
    double min_fluid_stop = 0;  ///< stop when active fluid < this fraction (0 = never)
    double wrn_parts_out = 1;   ///< warn when more than this % of the fluid is excluded
    double cfl_number = 0.2;    ///< from <constants><cflnumber>
    double vcpm_dt_coef = 0.8;  ///< VCPM sub-step = this * dp / c_S (SeaSpring's VcpmDtCoef)
    int vcpm_coupling = 2;      ///< 1: seed 000's staggered scheme; 2: staggered midpoint (symplectic only)
    int vcpm_contact = 0;       ///< 1: contact of VCPM solids (physics/solid_contact.h)
    double vcpm_contact_stiffness = 0.5;  ///< contact stiffness / first-neighbour bond stiffness
    double vcpm_contact_damping = 0.5;    ///< fraction of critical damping of the normal dashpot
    double vcpm_contact_friction = 0;     ///< Coulomb friction coefficient
    int vcpm_surface_correction = 1;      ///< 1: surface correction of the lattice (physics/vcpm_surface.h); 0: plain
    int vcpm_row_bending = 0;             ///< 1: the rows' own bending, with the surface correction (physics/vcpm_rows.h)
    /// The corrected lattice's sub-step factor: 0 Gershgorin, 1 eigenvalue (solver/solid_stability.h);
    /// VcpmSubStepBound -1 (auto, the default) resolves to 1 with the rows' bending, else 0.
    int vcpm_substep_bound = 0;
};

/// An axis-aligned box [m].
struct DomainBox {
    Vec3d min{0, 0, 0};
    Vec3d max{0, 0, 0};
};

/// The `key`, `value` pairs of `<parameters>`, in the order they are written.
using ParameterValues = std::vector<std::pair<std::string, std::string>>;

/// Appends `<parameters>` (one `<parameter key value>` per entry, then `<simulationdomain>`
/// with `<posmin>`, `<posmax>` as %.17g numbers) to `parent`.
void writeParameters(pugi::xml_node parent, const ParameterValues& values, const DomainBox& domain);

/// Reads the `<parameter>` entries of `parameters` (see file comment). `has_fluid`: Visco is
/// required only when the case has fluid. cfl_number is left at its default (it is a constant).
SolverParameters readSolverParameters(const XmlSource& src, pugi::xml_node parameters, bool has_fluid);

/// gencase: the checks of readSolverParameters (the same function) on the values gencase resolved
/// from a definition (`values`: every key, expressions evaluated, defaults filled in; `nodes`: the
/// `<parameter>` element of each key the definition gives, named in messages; `parameters`: the
/// `<parameters>` element, named for defaults).
SolverParameters checkSolverParameters(const XmlSource& src, pugi::xml_node parameters,
                                       std::map<std::string, pugi::xml_node> nodes, const ParameterValues& values);

/// Reads `<simulationdomain>` of `parameters`; posmin must lie below posmax in each axis
/// (equal allowed in y for 2D).
DomainBox readSimulationDomain(const XmlSource& src, pugi::xml_node parameters, int dimensions);

}  // namespace seaspring::model
