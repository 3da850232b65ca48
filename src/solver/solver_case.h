// SeaSpring — MIT licence.
/// \file solver_case.h
/// \brief The case as the solver sees it: gencase's resolved OUTDIR/NAME.xml (constants,
///        parameters, domain, particle blocks, motion) and OUTDIR/NAME.h5 (particles, bonds).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/particle_set.h"
#include "core/vec3.h"
#include "gencase/constants.h"
#include "gencase/motion.h"

namespace seaspring::solver {

/// One <fixed|moving|solid|fluid mk begin count> block of the resolved case.
struct MkBlock {
    ParticleType type = ParticleType::Fixed;
    int mk = 0;        ///< global MK
    int mk_local = 0;  ///< mkbound (boundaries, solids) or mkfluid (fluid)
    std::uint32_t begin = 0, count = 0;
};

/// `<parameters>` as the solver uses them (DualSPHysics meaning and defaults).
struct SolverParameters {
    int step_algorithm = 1;  ///< 1 Verlet, 2 symplectic
    int verlet_steps = 40;
    int kernel = 2;           ///< 1 cubic spline, 2 Wendland
    int visco_treatment = 1;  ///< 1 artificial, 2 laminar+SPS, 3 laminar
    double visco = 0, visco_bound_factor = 1;
    int density_dt = 0;  ///< 0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full
    double density_dt_value = 0.1;
    double coef_dt_min = 0.05, dt_ini = 0, dt_min = 0, dt_fixed = 0;
    bool dt_all_particles = false;
    double time_max = 0, time_out = 0;
    double rhop_out_min = 700, rhop_out_max = 1300;
    double min_fluid_stop = 0;  ///< stop when active fluid < this fraction (0 = never)
    double wrn_parts_out = 1;   ///< warn when more than this % of the fluid is excluded
    double cfl_number = 0.2;    ///< from <constants><cflnumber>
};

struct SolverCase {
    std::string xml_path, h5_path, name;
    gencase::CaseConstants constants;
    SolverParameters params;
    Vec3d domain_min{0, 0, 0}, domain_max{0, 0, 0};
    std::vector<MkBlock> blocks;
    std::uint32_t nfixed = 0, nmoving = 0, nsolid = 0, nfluid = 0;
    gencase::MotionSet motion;
    ParticleSet particles;
    std::optional<BondNetwork> bonds;  ///< only when the case has solids
};

/// Loads OUTDIR/NAME (or OUTDIR/NAME.xml) and its .h5. Errors name the file, line and value.
SolverCase loadSolverCase(const std::string& path);

/// Printable lines: particle counts by type, dp, h, c0, B, masses, domain.
std::vector<std::string> describeCase(const SolverCase& c);

}  // namespace seaspring::solver
