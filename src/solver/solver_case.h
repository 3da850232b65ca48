// SeaSpring — MIT licence.
/// \file solver_case.h
/// \brief The case as the solver sees it: gencase's resolved OUTDIR/NAME.xml (constants,
///        parameters, domain, particle blocks, motion, solids summary) and OUTDIR/NAME.h5
///        (particles, bonds), read and checked against each other.
///
/// loadSolverCase is strict: anything seaspring does not implement stops the run with
/// "FILE:LINE: <element> ...: ... is not supported by seaspring (supported: ...)", and so do
/// unknown or repeated `<parameter>` keys, unknown elements, and any disagreement between
/// the XML and the particle file. Keys that have no effect in the chosen configuration
/// (SlipMode and NoPenetration with DBC, ShiftCoef and ShiftTFS without shifting) are
/// checked to be numbers and otherwise ignored, as DualSPHysics does.
/// `<special><gauges>` are read (gencase::parseGauges); `<savedt>` is not evaluated (a note).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/particle_set.h"
#include "core/vec3.h"
#include "gencase/constants.h"
#include "gencase/gauge_spec.h"
#include "gencase/motion.h"

namespace seaspring::solver {

/// One `<fixed|moving|solid|fluid mk=.. mkbound|mkfluid=.. begin=.. count=..>` block of the
/// resolved case: the particles of one MK, a contiguous id range.
struct MkBlock {
    ParticleType type = ParticleType::Fixed;
    int mk = 0;        ///< global MK
    int mk_local = 0;  ///< mkbound (boundaries, solids) or mkfluid (fluid)
    std::uint32_t begin = 0, count = 0;
};

/// `<parameters>` as the solver uses them (DualSPHysics meaning and defaults).
struct SolverParameters {
    int step_algorithm = 1;   ///< 1 Verlet, 2 symplectic
    int verlet_steps = 40;    ///< Verlet: an Euler step every this many steps
    int kernel = 2;           ///< 1 cubic spline, 2 Wendland C2
    int visco_treatment = 1;  ///< 1 artificial, 2 laminar+SPS, 3 laminar
    double visco = 0;         ///< artificial alpha, or kinematic viscosity nu [m^2/s]
    double visco_bound_factor = 1;
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
};

/// One `<vcpmsolids><solid>` body of the resolved case: a boundary MK modelled as a VCPM
/// lattice solid, its material and its clamps.
struct SolidBody {
    int mkbound = 0;
    std::uint16_t mk = 0;                 ///< global MK of its particles
    std::vector<std::uint16_t> clamp_mk;  ///< global MKs of its clamp boundaries
    double density = 0, youngmod = 0, poissratio = 0;  ///< [kg/m^3], [Pa], [-]
    double critstretch = 0;               ///< relative bond elongation at breakage (0: never)
    double damping = 0;                   ///< multiplies sqrt(E/(rho dp^2)) (0: none)
    /// <pointload>: F(t) = force + rate t on the solid particle nearest to point [N].
    struct Load {
        Vec3d point{0, 0, 0}, force{0, 0, 0}, rate{0, 0, 0};
        int line = 0;
    };
    std::vector<Load> loads;
    int line = 0;                         ///< line in the resolved XML
};

struct SolverCase {
    std::string xml_path, h5_path;
    std::string name;  ///< case name: NAME of OUTDIR/NAME
    gencase::CaseConstants constants;
    SolverParameters params;
    Vec3d domain_min{0, 0, 0}, domain_max{0, 0, 0};  ///< <simulationdomain> (absolute) [m]
    std::vector<MkBlock> blocks;                     ///< in id order
    std::uint32_t nfixed = 0, nmoving = 0, nsolid = 0, nfluid = 0;
    gencase::MotionSet motion;         ///< empty when the case has none
    ParticleSet particles;             ///< id order
    std::optional<BondNetwork> bonds;  ///< only when the case has solids
    std::uint32_t solid_bodies = 0;    ///< <solid> entries of the resolved <vcpmsolids>
    std::vector<SolidBody> solids;     ///< the same entries, in file order
    gencase::GaugeSet gauges;          ///< <special><gauges> (empty when none)
    std::vector<std::string> notes;    ///< "FILE:LINE: ..." for sections read but not used
};

/// Loads and checks a case written by gencase. `path` is OUTDIR/NAME, OUTDIR/NAME.xml or
/// OUTDIR/NAME.h5; the particle file is the one named in `<files particles>` (relative to the
/// XML). Throws seaspring::Error naming the file, line and offending value.
SolverCase loadSolverCase(const std::string& path);

/// Printable lines (no trailing newline): particle counts by type, dp, h, c0, B, masses,
/// domain, motion and solids, and the notes.
std::vector<std::string> describeCase(const SolverCase& c);

}  // namespace seaspring::solver
