// SeaSpring — MIT licence.
/// \file simulation.cpp
/// \brief A run's setup (backend data, cell division, physics line) and its outputs (see simulation.h).
#include "solver/simulation.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "core/error.h"
#include "io/checkpoint_file.h"
#include "io/part_output.h"
#include "io/vtu_writer.h"
#include "io/xdmf_series.h"
#include "physics/eos_tait.h"
#include "solver/coupling_ledger.h"
#include "solver/cell_switch.h"
#include "solver/gauge_system.h"
#include "solver/grid_origin.h"
#include "solver/run_limits.h"
#include "solver/simulation_parts.h"

namespace seaspring::solver {

namespace fs = std::filesystem;

namespace {
std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}
const char* kernelName(int k) { return k == 1 ? "cubic spline" : "Wendland C2"; }
}  // namespace

std::string describePhysics(const SolverParameters& p, int dim, int cell_div, double skin, std::uint32_t pair_lanes,
                            double cell_switch) {
    std::ostringstream s;
    s << dim << "D, " << (p.step_algorithm == 2 ? "symplectic" : "Verlet");
    if (p.step_algorithm == 1) s << " (Euler every " << p.verlet_steps << ")";
    s << ", " << kernelName(p.kernel) << ", ";
    if (p.visco_treatment == 1) s << "artificial viscosity " << p.visco << " (boundary x" << p.visco_bound_factor << ")";
    else if (p.visco_treatment == 2) s << "laminar+SPS nu=" << p.visco;
    else s << "laminar nu=" << p.visco;
    if (p.visco_treatment != 1) s << (p.laminar_lattice_correction ? " (lattice-corrected)" : " (DualSPHysics' operator)");
    static const char* ddt[] = {"no DDT", "DDT Molteni", "DDT Fourtakas", "DDT Fourtakas full"};
    s << ", " << ddt[p.density_dt];
    if (p.density_dt > 0) s << " delta=" << p.density_dt_value;
    static const char* const kSlip[] = {"?", "vel=0", "no-slip", "free-slip"};
    if (p.boundary == 2) s << ", mDBC " << kSlip[p.slip_mode >= 1 && p.slip_mode <= 3 ? p.slip_mode : 0];
    else s << ", DBC";
    s << ", CFL " << p.cfl_number << ", cells of " << cellSizeLabel(cell_div >= 1 && cell_div < kCellModes ? cell_div : 0);
    if (skin > 0) s << " with a skin of " << skin << " cell";
    if (cell_switch > 0) s << " (h once " << cell_switch << " of the fluid shares them)";
    if (pair_lanes > 1) s << ", " << pair_lanes << " pair lanes";
    return s.str();
}

int resolveCellDiv(const SolverCase& c, int cell_div) {
    if (cell_div > 0) return cell_div;
    const double np = double(c.particles.size()), h = c.constants.h, dp = c.constants.dp;
    // Finest first: 3D h/2 where it is at least dp wide; dp where h/2 is narrower and 2h/3 wider
    // than dp (neither a whole number of spacings); else 2h/3. 2D: h.
    int modes[3] = {2, 0, 0};
    if (c.constants.dimensions == 3) {
        if (h >= 2.0 * dp * (1.0 - 1e-9)) modes[0] = 4;
        else if (h > 1.5 * dp * (1.0 + 1e-9)) modes[0] = physics::kCellDivSpacing;
        else modes[0] = 3;
        modes[1] = modes[0] == 3 ? 2 : 3;
        modes[2] = modes[0] == 3 ? 0 : 2;
    }
    for (int d : modes) {
        physics::CellGrid g;
        if (d > 0 &&
            physics::makeCellGrid(c.domain_min.x, c.domain_min.y, c.domain_min.z, c.domain_max.x, c.domain_max.y,
                                  c.domain_max.z, h, d, g, 0.0, dp) &&
            double(g.cellCount()) <= 16.0 * np + 1048576.0)
            return d;
    }
    return 1;
}

std::uint32_t resolvePairLanes(const SolverCase& c, int pair_lanes) {
    if (pair_lanes > 0) return std::uint32_t(pair_lanes);
    std::uint32_t lanes = 1;
    while (lanes < kAutoPairLanesMax && std::uint64_t(c.nfluid) * lanes < kPairLaneThreads) lanes *= 2;
    return lanes;
}

double resolveSkin(const SolverCase& c, const RunOptions& o) {
    if (o.skin) return *o.skin;
    return c.particles.size() < kSmallRunParticles ? kSmallRunSkinFraction : physics::kDefaultSkinFraction;
}

static MdbcSetup makeMdbcSetup(const SolverCase& c, std::uint32_t nbound) {
    const ParticleSet& ps = c.particles;
    if (ps.normal.empty())
        throwInputError(c.h5_path, 0,
                        "Boundary=2 (mDBC) needs the boundary normals, but the case file has no /particles/normal: "
                        "add an active <normals> section to the case definition (docs/case-format.md) and run "
                        "gencase again");
    if (ps.normal.size() != nbound)
        throwInputError(c.h5_path, 0, "/particles/normal has " + std::to_string(ps.normal.size()) +
                                          " entries, expected one per boundary particle (" + std::to_string(nbound) + ")");
    MdbcSetup m;
    m.enabled = true;
    m.slip = physics::SlipMode(c.params.slip_mode);
    m.constants.threshold = float(c.params.mdbc_threshold);
    m.constants.dp2 = float(c.constants.dp * c.constants.dp);
    m.constants.cs02 = float(c.constants.speedsound * c.constants.speedsound);
    m.constants.gx = float(c.constants.gravity.x);
    m.constants.gy = float(c.constants.gravity.y);
    m.constants.gz = float(c.constants.gravity.z);
    m.normal0.assign(nbound, physics::Float4{0, 0, 0, 0});
    std::uint32_t with = 0;
    for (std::uint32_t id = 0; id < nbound; ++id) {
        const Vec3f n = ps.normal[id];
        if (n.x == 0.f && n.y == 0.f && n.z == 0.f) continue;
        m.normal0[id] = physics::Float4{n.x, n.y, n.z, 0.f};
        ++with;
    }
    if (with == 0)
        throwInputError(c.h5_path, 0,
                        "Boundary=2 (mDBC) but no boundary particle has a normal (all of "
                        "/particles/normal is zero): check the <normals> geometry of the case definition");
    m.with_normal = with;
    return m;
}

BackendSetup makeBackendSetup(const SolverCase& c, int cell_div, double skin, int pair_lanes, double cell_switch) {
    using namespace physics;
    const double switch_fraction = resolveCellSwitch(c, cell_div, cell_switch);
    cell_div = resolveCellDiv(c, cell_div);
    const ParticleSet& ps = c.particles;
    const std::size_t np = ps.size();
    for (std::size_t i = 0; i < np; ++i)
        if (ps.id[i] != i)
            throwInputError(c.h5_path, 0, "particle " + std::to_string(i) + " has id " +
                            std::to_string(ps.id[i]) + " (ids must equal the particle order)");
    if (std::fabs(c.constants.gamma - 7.0) > 0)
        throwInputError(c.xml_path, 0, "<gamma> is " + std::to_string(c.constants.gamma) +
                        "; seaspring's Tait equation uses gamma = 7");
    const SolverParameters& p = c.params;
    BackendSetup s;
    s.physics.kernel = p.kernel == 1 ? KernelType::Cubic : KernelType::Wendland;
    s.physics.visco = p.visco_treatment == 1 ? Viscosity::Artificial
                      : p.visco_treatment == 2 ? Viscosity::LaminarSps : Viscosity::Laminar;
    s.physics.ddt = DensityDiffusion(p.density_dt);
    s.physics.dim = c.constants.dimensions;
    s.symplectic = p.step_algorithm == 2;
    s.pair_lanes = resolvePairLanes(c, pair_lanes);

    const double h = c.constants.h, dp = c.constants.dp, rho0 = c.constants.rhop0;
    FluidInputs fi;
    fi.h = h;
    fi.dp = dp;
    fi.dim = c.constants.dimensions;
    fi.cs0 = c.constants.speedsound;
    fi.b = c.constants.b;
    fi.rhop0 = rho0;
    fi.massfluid = c.constants.massfluid;
    fi.massbound = c.constants.massbound;
    fi.visco = p.visco;
    fi.visco_bound_factor = p.visco_bound_factor;
    if (p.visco_treatment != 1 && p.laminar_lattice_correction)
        fi.laminar_scale = 1.0 / laminarLatticeRatio(s.physics.kernel, h, dp, c.constants.dimensions);
    fi.ddt_value = p.density_dt_value;
    fi.gravity_z = c.constants.gravity.z;
    fi.dt_all_particles = p.dt_all_particles;
    s.fluid = makeFluidConstants(fi);
    s.sps = makeSpsConstants(dp, c.constants.dimensions);

    if (cell_div == kCellDivSpacing && !(dp <= 2.0 * h && cellsToReach(h, dp) <= kMaxSpacingReach))
        throwInputError(c.xml_path, 0, "-cellmode:dp needs dp <= 2h <= " + std::to_string(kMaxSpacingReach) +
                                           " dp (dp " + fmt("%g", dp) + " m, h " + fmt("%g", h) +
                                           " m): use another -cellmode");
    const GridOrigin origin = latticeCentredGridOrigin(c, cellSizeOfMode(h, dp, cell_div));
    s.grid_centred = origin.any();
    if (!makeCellGrid(origin.min[0], origin.min[1], origin.min[2], c.domain_max.x, c.domain_max.y, c.domain_max.z,
                      h, cell_div, s.grid, skin, dp))
        throwInputError(c.xml_path, 0, "the simulation domain is too large for the cell grid (" +
                        std::to_string(s.grid.ncx) + " x " + std::to_string(s.grid.ncy) + " x " +
                        std::to_string(s.grid.ncz) + " cells of " + fmt("%g", s.grid.cellsize) + " m)");
    if (switch_fraction > 0) {  // the cells of h the run switches to (cell_switch.h)
        const GridOrigin o = latticeCentredGridOrigin(c, cellSizeOfMode(h, dp, 2));
        s.cell_switch.on = makeCellGrid(o.min[0], o.min[1], o.min[2], c.domain_max.x, c.domain_max.y,
                                        c.domain_max.z, h, 2, s.cell_switch.grid, skin, dp);
        s.cell_switch.fraction = switch_fraction;
    }
    StepConstants& st = s.step;
    st.gx = c.constants.gravity.x;
    st.gy = c.constants.gravity.y;
    st.gz = c.constants.gravity.z;
    st.minx = c.domain_min.x;
    st.miny = c.domain_min.y;
    st.minz = c.domain_min.z;
    st.maxx = c.domain_max.x;
    st.maxy = c.domain_max.y;
    st.maxz = c.domain_max.z;
    st.rhop0 = float(rho0);
    st.rhop_out_min = float(p.rhop_out_min);
    st.rhop_out_max = float(p.rhop_out_max);

    s.nbound = c.nfixed + c.nmoving + c.nsolid;  // solids are DBC boundary particles for the fluid
    s.nfluid = c.nfluid;
    s.first_moving = c.nfixed;
    s.nmoving = c.nmoving;
    s.pos.resize(np);
    s.velrho.resize(np);
    for (std::size_t i = 0; i < np; ++i) {
        s.pos[i] = Double3{ps.pos[i].x, ps.pos[i].y, ps.pos[i].z};
        s.velrho[i] = Float4{ps.vel[i].x, ps.vel[i].y, ps.vel[i].z, ps.rhop[i]};
    }
    // Moving boundaries: which motion object moves each one.
    std::vector<int> object_of_block;
    for (const MkBlock& blk : c.blocks) {
        if (blk.type != ParticleType::Moving) continue;
        int index = -1;
        for (std::size_t o = 0; o < c.motion.objects.size(); ++o)
            if (c.motion.objects[o].mkbound == blk.mk_local) index = int(o);
        if (index < 0)
            throwInputError(c.xml_path, 0, "moving boundary mkbound=" + std::to_string(blk.mk_local) +
                            " has no <objreal> in <motion>");
        for (std::uint32_t k = 0; k < blk.count; ++k) {
            const std::uint32_t id = blk.begin + k;
            s.moving_pos0.push_back(s.pos[id]);
            s.moving_object.push_back(std::uint16_t(index));
        }
    }
    if (s.moving_pos0.size() != c.nmoving)
        throwInputError(c.xml_path, 0, "the moving blocks hold " + std::to_string(s.moving_pos0.size()) +
                        " particles but nmoving is " + std::to_string(c.nmoving));
    s.motion_objects = std::uint32_t(c.motion.objects.size());
    s.solid = makeSolidSetup(c);
    if (p.boundary == 2) s.mdbc = makeMdbcSetup(c, s.nbound);
    return s;
}

Simulation::Simulation(const SolverCase& c, const RunOptions& o, std::unique_ptr<Backend> backend,
                       std::ostream& log)
    : case_(c), opt_(o), backend_(std::move(backend)), log_(log) {
    checkRunMemory(c, backend_->name() == "gpu");
    setup_ = makeBackendSetup(c, o.cell_div, resolveSkin(c, o), o.pair_lanes, o.cell_switch);
    checkSolidSubstep(c, setup_.solid);
    health_ = std::make_shared<Health>(c, setup_, opt_);
    fs::create_directories(opt_.outdir);
    if (!opt_.restart_file.empty()) {
        resume_ = std::make_shared<const CheckpointData>(io::readCheckpointFile(opt_.restart_file));
        continuing_ = restartContinuesIn(opt_.restart_file, opt_.outdir);
    }
    const CheckpointData* cont = continuing_ ? resume_.get() : nullptr;  // files continued
    // Part files behind the run on the GPU (the host thread waits for the device there); at
    // once on the CPU, whose threads the write would slow.
    if (opt_.save_h5) out_ = std::make_shared<Output>(opt_.outdir, backend_->name() == "gpu");
    if (!setup_.solid.empty())
        ledger_ = std::make_shared<Ledger>(opt_.outdir, cont ? cont->integer("ledger/offset") : -1,
                                           setup_.solid.contact_on);
    if (!c.gauges.empty()) gauges_ = std::make_shared<GaugeSystem>(c, opt_.outdir, log_, resume_.get());
    sum_.case_name = c.name;
    sum_.backend = backend_->name();
    sum_.device = backend_->deviceName();
    sum_.threads = backend_->threads();
    sum_.np = std::uint32_t(c.particles.size());
    sum_.nfixed = c.nfixed;
    sum_.nmoving = c.nmoving;
    sum_.nsolid = c.nsolid;
    sum_.nfluid = c.nfluid;
    sum_.options =
        describePhysics(c.params, c.constants.dimensions, setup_.grid.cell_div, resolveSkin(c, o), setup_.pair_lanes,
                        setup_.cell_switch.on ? setup_.cell_switch.fraction : 0.0);
    sum_.bonds = setup_.solid.bonds;
    sum_.clamp_bonds = setup_.solid.clamp_bonds;
    if (setup_.grid_centred) {
        const physics::CellGrid& g = setup_.grid;
        log_ << "  cell grid from (" << fmt("%.9g", g.minx) << ", " << fmt("%.9g", g.miny) << ", " << fmt("%.9g", g.minz)
             << ") m: the fluid's lattice half a spacing from the cell faces\n";
    }
    if (setup_.mdbc.enabled)
        log_ << "  mDBC: " << setup_.mdbc.with_normal << " of " << setup_.nbound
             << " boundary particles have a ghost node"
             << (c.nsolid > 0 ? " (VCPM solid particles: theirs follow the lattice's deformation)" : "") << "\n";
    if (!setup_.solid.empty()) {
        for (const std::string& l : setup_.solid.body_lines) log_ << "  " << l << "\n";
        log_ << "  VCPM sub-step " << setup_.solid.dt << " s (VcpmDtCoef " << c.params.vcpm_dt_coef
             << "), " << setup_.solid.bonds << " bonds, " << setup_.solid.clamp_bonds << " clamp bonds, "
             << setup_.solid.nclamp << " clamp nodes"
             << (c.nfluid == 0 ? "; no fluid: solid only"
                 : c.params.vcpm_coupling == 2 && c.params.step_algorithm == 2
                     ? "; coupling: staggered midpoint (VcpmCoupling 2)"
                     : "; coupling: staggered as seed 000 (VcpmCoupling 1)")
             << "\n";
    }
}

bool Simulation::healthy(HostState& st, double time, long long step) {
    Health& h = *health_;
    std::optional<BlowupDiagnosis> d = h.check.scan(st, time, step, h.dt);
    for (const std::string& w : h.check.takeWarnings()) log_ << w << "\n";
    sum_.solids_outside = h.check.solidsOutside();
    if (d) {
        blownUp(std::move(*d));
        return false;
    }
    std::swap(h.last_good, st);
    h.good_time = time;
    h.good_step = step;
    return true;
}

bool Simulation::checkStep(double t, long long step, double dt, std::uint32_t active, long long dtmin_hits,
                           bool output_due) {
    Health& h = *health_;
    h.dt = dt;
    if (std::optional<BlowupDiagnosis> d = h.check.afterStep(t, step, dt, active, dtmin_hits)) {
        blownUp(std::move(*d));
        return false;
    }
    // Solids: the backend's per-step test; when it finds a particle past a bound, the scan now
    // (it names the particles and the option; a state that passes it goes on).
    const bool solid_alarm = !setup_.solid.empty() && backend_->solidsPastBounds() > 0;
    if (output_due || (!solid_alarm && !h.check.scanDue(step))) return true;
    // A quick scan (blowup_check.h): the backend counts the non-finite particles; only a count
    // above zero, a solid alarm or a kept scan brings the whole state to the host.
    if (!solid_alarm && !h.check.keepDue() && !backend_->forcesAhead() && backend_->notFiniteCount() == 0) {
        backend_->downloadSolidPositions(h.solid_pos);
        h.check.quickScan(h.solid_pos, t, step);
        for (const std::string& w : h.check.takeWarnings()) log_ << w << "\n";
        sum_.solids_outside = h.check.solidsOutside();
        return true;
    }
    backend_->download(h.scan);
    return healthy(h.scan, t, step);
}

void Simulation::stepFailed(double t, long long step, const std::string& what) {
    blownUp(health_->check.nonFiniteStep(t, step, what));
}

double Simulation::lastOutputTime() const { return health_->written_time; }

void Simulation::blownUp(BlowupDiagnosis d) {
    Health& h = *health_;
    if (d.particles.empty()) {  // a per-step diagnosis: name the particles from the state
        HostState st;
        backend_->download(st);
        h.check.describe(d, st);
    }
    log_ << "error: " << describeBlowup(d) << "\n";
    if (h.good_time > h.written_time) {
        writeOutput(h.last_good, h.good_time, h.good_step, false);
        log_ << "  the last good state (t=" << h.good_time << " s, step " << h.good_step << ") is written as "
             << (h.written_file.empty() ? "the last output" : h.written_file) << "\n";
    }
    sum_.last_good_output = h.written_file;
    sum_.last_good_time = h.written_time;
    sum_.stop_reason = "blow-up: " + d.quantity;
    sum_.exit_code = 1;
    sum_.blowup = std::move(d);
}

bool Simulation::outputNeedsState() const {
    return opt_.save_h5 || opt_.save_vtk || observer_ || !setup_.solid.empty();
}

bool Simulation::output(double time, long long step) {
    const auto t0 = std::chrono::steady_clock::now();
    struct AddTime {  // to sum_.output_time, whichever way the output ends
        std::chrono::steady_clock::time_point t0;
        double& sum;
        ~AddTime() { sum += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
    } add{t0, sum_.output_time};
    Health& h = *health_;
    if (!outputNeedsState() && !backend_->forcesAhead() && backend_->notFiniteCount() == 0) {
        noteOutput(time);  // nothing reads the state, and no particle is not finite
        return true;
    }
    backend_->download(h.scan);
    if (!healthy(h.scan, time, step)) return false;
    writeOutput(h.last_good, time, step, true);  // the state just downloaded (healthy swapped it in)
    return true;
}

void Simulation::writeOutput(const HostState& st, double time, long long step, bool ledger) {
    if (observer_) observer_(time, step, st);
    if (!setup_.solid.empty() && ledger) {
        const Vec3d g = case_.constants.gravity;
        std::vector<physics::Double3> boundary_force;
        if (case_.nfluid > 0) backend_->boundaryForces(boundary_force);
        ledger_->file.add(ledgerRow(time, st, setup_.solid, case_.particles.pos, setup_.nbound,
                                    case_.constants.massfluid, physics::Double3{g.x, g.y, g.z}, boundary_force));
    }
    if (opt_.save_h5 || opt_.save_vtk) writeParticleFiles(st, time, step);
    noteOutput(time);
}

void Simulation::writeParticleFiles(const HostState& st, double time, long long step) {
    const std::size_t np = st.pos.size();
    // The arrays of the last part file, refilled in place (io::PartWriter::takeSpare), on the
    // backend's host threads (each element on its own: the same values on any number).
    io::PartArrays a = opt_.save_h5 ? out_->parts.takeSpare() : io::PartArrays{};
    a.pos.resize(3 * np);
    a.vel.resize(3 * np);
    a.rhop.resize(np);
    a.press.resize(np);
    a.type.resize(np);
    std::vector<double>& pos = a.pos;
    std::vector<float>& vel = a.vel;
    std::vector<float>& rhop = a.rhop;
    std::vector<float>& press = a.press;
    std::vector<std::uint8_t>& type = a.type;
    const float b = setup_.fluid.cteb, ovrho0 = setup_.fluid.ovrhop0;
    const int threads = backend_->hostThreads();
    const long long n = static_cast<long long>(np);
    const ParticleType* ptype = case_.particles.type.data();
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
    for (long long i = 0; i < n; ++i) {
        pos[3 * i] = st.pos[i].x;
        pos[3 * i + 1] = st.pos[i].y;
        pos[3 * i + 2] = st.pos[i].z;
        vel[3 * i] = st.velrho[i].x;
        vel[3 * i + 1] = st.velrho[i].y;
        vel[3 * i + 2] = st.velrho[i].z;
        rhop[i] = st.velrho[i].w;
        press[i] = physics::taitPressure7(rhop[i], b, ovrho0);
        type[i] = std::uint8_t(ptype[i]);
    }
    std::vector<float>& disp = a.disp;
    std::vector<float>& strain = a.strain;
    std::vector<float>& damage = a.damage;
    std::vector<std::uint8_t>& broken = a.broken;
    if (!setup_.solid.empty()) {
        solidFields(st, disp, strain, broken, damage);
    }
    if (opt_.save_vtk) {
        ParticleSet p = case_.particles;
        for (std::size_t i = 0; i < np; ++i) {
            p.pos[i] = Vec3d{st.pos[i].x, st.pos[i].y, st.pos[i].z};
            p.vel[i] = Vec3f{st.velrho[i].x, st.velrho[i].y, st.velrho[i].z};
            p.rhop[i] = st.velrho[i].w;
        }
        char name[64];
        std::snprintf(name, sizeof name, "part_%04d.vtu", out_index_);
        fs::create_directories(fs::path(opt_.outdir) / "vtk");
        std::vector<io::VtuExtraArray> extra = {{"press", press}, {"excluded", st.excl}};
        if (!disp.empty()) {
            std::vector<float> dmag(np);
            for (std::size_t i = 0; i < np; ++i)
                dmag[i] = std::sqrt(disp[3 * i] * disp[3 * i] + disp[3 * i + 1] * disp[3 * i + 1] +
                                    disp[3 * i + 2] * disp[3 * i + 2]);
            extra.push_back({"disp", dmag});
            extra.push_back({"strain", strain});
            extra.push_back({"broken", broken});
            extra.push_back({"damage", damage});
        }
        io::writeParticlesVtu((fs::path(opt_.outdir) / "vtk" / name).string(), p, extra);
    }
    if (opt_.save_h5) {  // last: its arrays move to the part writer
        a.index = out_index_;
        a.time = time;
        a.step = step;
        a.np = np;
        a.excluded = st.excl;
        const bool solid = !disp.empty();
        a.id = case_.particles.id.data();
        a.mk = case_.particles.mk.data();
        a.mass = case_.particles.mass.data();
        a.constants = {case_.constants.h, case_.constants.dp, kernelName(case_.params.kernel),
                       case_.constants.rhop0, case_.constants.dimensions, case_.constants.b};
        const std::string rel = out_->parts.submit(std::move(a));
        out_->xdmf.add(rel, time, np, solid);
        health_->written_file = rel;
    }
}

void Simulation::noteOutput(double time) {
    if (gauges_) gauges_->flush();
    health_->written_time = time;
    ++out_index_;
    sum_.outputs = out_index_;
}

}  // namespace seaspring::solver
