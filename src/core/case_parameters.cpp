// SeaSpring — MIT licence.
/// \file case_parameters.cpp
#include "core/case_parameters.h"

namespace seaspring {

const std::vector<ParameterInfo>& knownParameters() {
    using K = ParameterKind;
    static const std::vector<ParameterInfo> table = {
        {"SavePosDouble", "0", K::Number, "save positions in double precision (SeaSpring always does)"},
        {"Boundary", "1", K::Number, "boundary method 1:DBC, 2:mDBC"},
        {"SlipMode", "1", K::Number, "mDBC slip mode 1:DBC vel=0, 2:no-slip, 3:free-slip"},
        {"NoPenetration", "0", K::Number, "mDBC no-penetration correction"},
        {"MDbcThreshold", "0", K::Number, "mDBC slip mode 1: kernel sum below which a boundary particle takes rho0 (0..1)"},
        {"StepAlgorithm", "1", K::Number, "time integration 1:Verlet, 2:Symplectic"},
        {"VerletSteps", "40", K::Number, "Verlet: steps between Euler resynchronisations"},
        {"Kernel", "2", K::Number, "kernel 1:cubic spline, 2:Wendland C2"},
        {"ViscoTreatment", "1", K::Number, "viscosity 1:artificial, 2:laminar+SPS, 3:laminar"},
        {"Visco", nullptr, K::Number, "artificial alpha, or kinematic viscosity nu [m^2/s]"},
        {"ViscoBoundFactor", "1", K::Number, "viscosity multiplier for fluid-boundary pairs"},
        {"ViscoTime", "NONE", K::Text, "file with viscosity against time"},
        {"DensityDT", "0", K::Number, "density diffusion 0:none, 1:Molteni, 2:Fourtakas, 3:Fourtakas full"},
        {"DensityDTvalue", "0.1", K::Number, "density diffusion coefficient delta"},
        {"Shifting", "0", K::Number, "particle shifting 0:none, 1:no bound, 2:no fixed, 3:full"},
        {"ShiftCoef", "-2", K::Number, "shifting coefficient"},
        {"ShiftTFS", "0", K::Number, "shifting free-surface threshold"},
        {"RigidAlgorithm", "1", K::Number, "floating bodies 0:free, 1:SPH, 2:DEM, 3:Chrono"},
        {"FtPause", "0", K::Number, "time floating bodies stay frozen [s]"},
        {"FtIgnoreRadius", "0", K::Number, "ignore floating radius with periodic conditions"},
        {"CoefDtMin", "0.05", K::Number, "DtMin = CoefDtMin*h/c0"},
        {"DtIni", "0", K::Number, "initial time step [s] (0: h/c0)"},
        {"DtMin", "0", K::Number, "minimum time step [s] (0: CoefDtMin*h/c0)"},
        {"DtFixed", "0", K::Number, "fixed time step [s] (0: variable)"},
        {"DtFixedFile", "NONE", K::Text, "file with dt against time [ms]"},
        {"DtAllParticles", "0", K::Number, "1: boundary velocities enter the dt criterion"},
        {"TimeMax", nullptr, K::Number, "simulated time [s]"},
        {"TimeOut", nullptr, K::Number, "output interval [s]"},
        {"TimeOutExtra", "-1", K::Number, "extra output interval for motion data [s]"},
        {"RhopOutMin", "700", K::Number, "particles below this density are excluded [kg/m^3]"},
        {"RhopOutMax", "1300", K::Number, "particles above this density are excluded [kg/m^3]"},
        {"MinFluidStop", "0.1", K::Number,
         "stop (a blow-up, exit 1) when the active fluid falls below this fraction of the initial fluid (0: never)"},
        {"WrnPartsOut", "1", K::Number, "warn when many particles are excluded"},
        {"PartsOutMax", "1", K::Deprecated, "deprecated in DualSPHysics"},
        {"PosDouble", "0", K::Deprecated, "deprecated in DualSPHysics"},
        {"IncZ", "0", K::Deprecated, "deprecated: use <simulationdomain>"},
        {"DomainFixed", "", K::Deprecated, "deprecated: use <simulationdomain>"},
        {"DomainFixedXmin", "0", K::Deprecated, "deprecated: use <simulationdomain>"},
        {"DomainFixedXmax", "0", K::Deprecated, "deprecated: use <simulationdomain>"},
        {"DomainFixedYmin", "0", K::Deprecated, "deprecated: use <simulationdomain>"},
        {"DomainFixedYmax", "0", K::Deprecated, "deprecated: use <simulationdomain>"},
        {"DomainFixedZmin", "0", K::Deprecated, "deprecated: use <simulationdomain>"},
        {"DomainFixedZmax", "0", K::Deprecated, "deprecated: use <simulationdomain>"},
        {"XPeriodicIncY", "0", K::Number, "periodic in x: y increment"},
        {"XPeriodicIncZ", "0", K::Number, "periodic in x: z increment"},
        {"YPeriodicIncX", "0", K::Number, "periodic in y: x increment"},
        {"YPeriodicIncZ", "0", K::Number, "periodic in y: z increment"},
        {"ZPeriodicIncX", "0", K::Number, "periodic in z: x increment"},
        {"ZPeriodicIncY", "0", K::Number, "periodic in z: y increment"},
        {"XYPeriodic", "0", K::Number, "periodic in x and y"},
        {"XZPeriodic", "0", K::Number, "periodic in x and z"},
        {"YZPeriodic", "0", K::Number, "periodic in y and z"},
        {"Symmetry", "0", K::Number, "symmetry plane y=0"},
        {"DivCleanKp", "0", K::Number, "divergence cleaning coefficient"},
        {"VcpmDtCoef", "0.8", K::Number, "VCPM solid sub-step = VcpmDtCoef*dp/c_S (SeaSpring)"},
        {"VcpmCoupling", "2", K::Number, "VCPM coupling 1:staggered as seed 000, 2:staggered midpoint (SeaSpring)"},
        {"VcpmContact", "0", K::Number, "contact of VCPM solids 0:none, 1:solid-solid and solid-wall (SeaSpring)"},
        {"VcpmContactStiffness", "0.5", K::Number, "VCPM contact stiffness / first-neighbour bond stiffness (SeaSpring)"},
        {"VcpmContactDamping", "0.5", K::Number, "VCPM contact normal damping, fraction of critical (SeaSpring)"},
        {"VcpmContactFriction", "0", K::Number, "VCPM contact Coulomb friction coefficient (SeaSpring)"},
        {"LaminarLatticeCorrection", "1", K::Number, "laminar viscosity 0:DualSPHysics' operator (1.1-1.5% weak on the particle lattice), 1:that bias divided out (SeaSpring)"},
        {"VcpmSurfaceCorrection", "1", K::Number, "VCPM surface correction 0:none (the plain lattice), 1:surface springs, volumetric weights and clamp bonds (SeaSpring)"},
        {"VcpmRowBending", "-1", K::Number, "VCPM rows' own bending -1:auto (1 with VcpmSurfaceCorrection 1, else 0), 0:off, 1:on (SeaSpring)"},
        {"VcpmSubStepBound", "-1", K::Number, "VCPM sub-step factor of the corrected lattice -1:auto (1 with VcpmRowBending 1, else 0), 0:Gershgorin's bounds, 1:the bodies' largest stiffness eigenvalues (SeaSpring)"},
    };
    return table;
}

const ParameterInfo* findParameter(const std::string& key) {
    for (const ParameterInfo& p : knownParameters())
        if (key == p.key) return &p;
    return nullptr;
}

}  // namespace seaspring
