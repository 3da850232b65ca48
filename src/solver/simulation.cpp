// SeaSpring — MIT licence.
/// \file simulation.cpp
/// \brief The time loop (see simulation.h).
#include "solver/simulation.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "core/error.h"
#include "io/part_output.h"
#include "io/vtu_writer.h"
#include "io/xdmf_series.h"
#include "physics/eos_tait.h"
#include "solver/coupling_ledger.h"
#include "solver/gauge_system.h"
#include "solver/motion_player.h"
#include "solver/state_hash.h"

namespace seaspring::solver {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {
double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}
std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}
const char* kernelName(int k) { return k == 1 ? "cubic spline" : "Wendland C2"; }
}  // namespace

std::string describePhysics(const SolverParameters& p, int dim, int cell_div) {
    std::ostringstream s;
    s << dim << "D, " << (p.step_algorithm == 2 ? "symplectic" : "Verlet");
    if (p.step_algorithm == 1) s << " (Euler every " << p.verlet_steps << ")";
    s << ", " << kernelName(p.kernel) << ", ";
    if (p.visco_treatment == 1) s << "artificial viscosity " << p.visco << " (boundary x" << p.visco_bound_factor << ")";
    else if (p.visco_treatment == 2) s << "laminar+SPS nu=" << p.visco;
    else s << "laminar nu=" << p.visco;
    static const char* ddt[] = {"no DDT", "DDT Molteni", "DDT Fourtakas", "DDT Fourtakas full"};
    s << ", " << ddt[p.density_dt];
    if (p.density_dt > 0) s << " delta=" << p.density_dt_value;
    static const char* const kCells[] = {"?", "2h", "h", "2h/3", "h/2"};
    s << ", DBC, CFL " << p.cfl_number << ", cells of " << kCells[cell_div >= 1 && cell_div <= 4 ? cell_div : 0];
    return s.str();
}

int resolveCellDiv(const SolverCase& c, int cell_div) {
    if (cell_div > 0) return cell_div;
    const double np = double(c.particles.size());
    for (int d = c.constants.dimensions == 3 ? 4 : 2; d > 1; --d) {
        physics::CellGrid g;
        if (physics::makeCellGrid(c.domain_min.x, c.domain_min.y, c.domain_min.z, c.domain_max.x, c.domain_max.y,
                                  c.domain_max.z, c.constants.h, d, g) &&
            double(g.cellCount()) <= 16.0 * np + 1048576.0)
            return d;
    }
    return 1;
}

BackendSetup makeBackendSetup(const SolverCase& c, int cell_div) {
    using namespace physics;
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
    fi.ddt_value = p.density_dt_value;
    fi.gravity_z = c.constants.gravity.z;
    fi.dt_all_particles = p.dt_all_particles;
    s.fluid = makeFluidConstants(fi);
    s.sps = makeSpsConstants(dp, c.constants.dimensions);

    if (!makeCellGrid(c.domain_min.x, c.domain_min.y, c.domain_min.z, c.domain_max.x, c.domain_max.y,
                      c.domain_max.z, h, cell_div, s.grid))
        throwInputError(c.xml_path, 0, "the simulation domain is too large for the cell grid (" +
                        std::to_string(s.grid.ncx) + " x " + std::to_string(s.grid.ncy) + " x " +
                        std::to_string(s.grid.ncz) + " cells of " + fmt("%g", s.grid.cellsize) + " m)");
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
    return s;
}

struct Simulation::Output {
    io::XdmfSeries xdmf;
    explicit Output(const std::string& dir) : xdmf(dir) {}
};

struct Simulation::Ledger {
    LedgerFile file;
    explicit Ledger(const std::string& dir) : file(dir) {}
};

Simulation::Simulation(const SolverCase& c, const RunOptions& o, std::unique_ptr<Backend> backend,
                       std::ostream& log)
    : case_(c), opt_(o), backend_(std::move(backend)), log_(log) {
    setup_ = makeBackendSetup(c, o.cell_div);
    fs::create_directories(opt_.outdir);
    if (opt_.save_h5) out_ = std::make_shared<Output>(opt_.outdir);
    if (!setup_.solid.empty()) ledger_ = std::make_shared<Ledger>(opt_.outdir);
    if (!c.gauges.empty()) gauges_ = std::make_shared<GaugeSystem>(c, setup_, opt_.outdir, log_);
    sum_.case_name = c.name;
    sum_.backend = backend_->name();
    sum_.device = backend_->deviceName();
    sum_.threads = backend_->threads();
    sum_.np = std::uint32_t(c.particles.size());
    sum_.nfixed = c.nfixed;
    sum_.nmoving = c.nmoving;
    sum_.nsolid = c.nsolid;
    sum_.nfluid = c.nfluid;
    sum_.options = describePhysics(c.params, c.constants.dimensions, setup_.grid.range);
    sum_.bonds = setup_.solid.bonds;
    sum_.clamp_bonds = setup_.solid.clamp_bonds;
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

std::vector<physics::RigidMotionGpu> Simulation::motionsOver(double time, double interval) const {
    std::vector<physics::RigidMotionGpu> m(case_.motion.objects.size());
    for (std::size_t o = 0; o < m.size(); ++o) {
        const RigidTransform a = motionTransformAt(case_.motion.objects[o], time);
        const RigidTransform b = motionTransformAt(case_.motion.objects[o], time + interval);
        for (int r = 0; r < 3; ++r) {
            for (int col = 0; col < 3; ++col) {
                m[o].r[3 * r + col] = a.r[r][col];
                m[o].r_next[3 * r + col] = b.r[r][col];
            }
            m[o].t[r] = a.t[r];
            m[o].t_next[r] = b.t[r];
        }
        m[o].inv_dt = 1.0 / interval;
    }
    return m;
}

void Simulation::placeMoving(double time, double interval) {
    if (setup_.nmoving == 0) return;
    backend_->applyMotion(motionsOver(time, interval));
}

double Simulation::limitDt(double dt) {
    const double h = case_.constants.h, cs0 = case_.constants.speedsound;
    const double dtmin = case_.params.dt_min > 0 ? case_.params.dt_min : case_.params.coef_dt_min * h / cs0;
    if (!std::isfinite(dt))
        throw Error("the time step is not finite (dt = " + fmt("%g", dt) +
                    "): the simulation became unstable; check the last output");
    if (dt < dtmin) {
        ++sum_.dtmin_hits;
        return dtmin;
    }
    return dt;
}

void Simulation::output(double time, long long step) {
    HostState st;
    backend_->download(st);
    if (observer_) observer_(time, step, st);
    const std::size_t np = st.pos.size();
    std::vector<double> pos(3 * np);
    std::vector<float> vel(3 * np), rhop(np), press(np);
    std::vector<std::uint8_t> type(np);
    const float b = setup_.fluid.cteb, ovrho0 = setup_.fluid.ovrhop0;
    for (std::size_t i = 0; i < np; ++i) {
        pos[3 * i] = st.pos[i].x;
        pos[3 * i + 1] = st.pos[i].y;
        pos[3 * i + 2] = st.pos[i].z;
        vel[3 * i] = st.velrho[i].x;
        vel[3 * i + 1] = st.velrho[i].y;
        vel[3 * i + 2] = st.velrho[i].z;
        rhop[i] = st.velrho[i].w;
        press[i] = physics::taitPressure7(rhop[i], b, ovrho0);
        type[i] = std::uint8_t(case_.particles.type[i]);
    }
    std::vector<float> disp, strain, damage;
    std::vector<std::uint8_t> broken;
    if (!setup_.solid.empty()) {
        checkSolidFinite(st, time);
        solidFields(st, disp, strain, broken, damage);
        const Vec3d g = case_.constants.gravity;
        std::vector<physics::Double3> boundary_force;
        if (case_.nfluid > 0) backend_->boundaryForces(boundary_force);
        ledger_->file.add(ledgerRow(time, st, setup_.solid, case_.particles.pos, setup_.nbound,
                                    case_.constants.massfluid, physics::Double3{g.x, g.y, g.z}, boundary_force));
    }
    if (opt_.save_h5) {
        io::PartFrame f;
        if (!disp.empty()) {
            f.disp = disp.data();
            f.strain = strain.data();
            f.broken = broken.data();
            f.damage = damage.data();
        }
        f.index = out_index_;
        f.time = time;
        f.step = step;
        f.np = np;
        f.pos = pos.data();
        f.vel = vel.data();
        f.rhop = rhop.data();
        f.press = press.data();
        f.id = case_.particles.id.data();
        f.type = type.data();
        f.mk = case_.particles.mk.data();
        f.excluded = st.excl.data();
        const std::string rel = io::writePartH5(opt_.outdir, f);
        out_->xdmf.add(rel, time, np, !disp.empty());
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
    if (gauges_) gauges_->flush();
    ++out_index_;
    sum_.outputs = out_index_;
}

RunSummary Simulation::run() {
    const auto t_start = Clock::now();
    const SolverParameters& p = case_.params;
    const double h = case_.constants.h, cs0 = case_.constants.speedsound, cfl = p.cfl_number;
    const double tmax = p.time_max, tout = p.time_out;
    const long long max_steps = opt_.nsteps ? *opt_.nsteps : -1;
    const bool symplectic = p.step_algorithm == 2;

    backend_->init(setup_);
    placeMoving(0.0, p.dt_ini > 0 ? p.dt_ini : h / cs0);
    backend_->divide(false);
    if (gauges_) {
        gauges_->attach(*backend_);
        gauges_->evaluate(0.0, *backend_);
    }
    output(0.0, 0);

    // SEASPRING_TIMERS=1: wall time per phase (synchronising the device after each phase).
    const bool timers = std::getenv("SEASPRING_TIMERS") != nullptr;
    double t_divide = 0, t_forces = 0, t_integrate = 0, t_other = 0, t_solid = 0;
    const bool solids = !setup_.solid.empty();
    const bool solid_only = solids && case_.nfluid == 0;
    const bool midpoint = solids && !solid_only && symplectic && p.vcpm_coupling == 2;
    const double solid_dt = p.dt_fixed > 0 && solid_only ? std::min(p.dt_fixed, setup_.solid.dt) : setup_.solid.dt;
    bool clamp_moves = false;
    for (std::int16_t o : setup_.solid.clamp_object) clamp_moves = clamp_moves || o >= 0;
    auto phase = [&](double& acc, auto&& fn) {
        if (!timers) return fn();
        const auto a = Clock::now();
        auto r = fn();
        backend_->synchronize();
        acc += seconds(a, Clock::now());
        return r;
    };
    auto forces = [&] { return phase(t_forces, [&] { return backend_->computeForces(); }); };
    auto predictor = [&](double dt) { phase(t_integrate, [&] { backend_->symplecticPredictor(dt); return 0; }); };
    auto corrector = [&](double dt) { phase(t_integrate, [&] { backend_->symplecticCorrector(dt); return 0; }); };
    auto verlet = [&](double dt, bool e) { phase(t_integrate, [&] { backend_->verletStep(dt, e); return 0; }); };
    auto divide = [&](bool keep_step_start) {
        phase(t_divide, [&] { backend_->divide(keep_step_start); return 0; });
    };
    double t = 0, dt_next = p.dt_ini > 0 ? p.dt_ini : h / cs0, dt_prev = dt_next;
    double next_out = tout;
    long long step = 0;
    int verlet_count = 0;
    const auto t_loop = Clock::now();
    auto t_progress = t_loop;
    bool warned_out = false;
    sum_.stop_reason = "TimeMax reached";
    while (t < tmax - 1e-12 * tmax) {
        if (max_steps >= 0 && step >= max_steps) {
            sum_.stop_reason = "step limit (-nsteps) reached";
            break;
        }
        double dt;
        if (solid_only) {
            // No fluid: the solid advances by its own sub-step, in chunks up to the next output
            // (one sub-step per chunk when a clamp moves, so that it follows its motion law).
            dt = solid_dt;
            const double until = std::min({next_out, tmax, gauges_ ? gauges_->nextTime() : tmax});
            long long n = std::max(1LL, (long long)std::ceil((until - t) / dt - 1e-9));
            if (clamp_moves) n = 1;
            if (max_steps >= 0) n = std::min(n, max_steps - step);
            phase(t_integrate, [&] { solidOnlySteps(t, n, dt); return 0; });
            t += double(n) * dt;
            step += n;
            placeMoving(t, dt);
        } else {
            if (symplectic) {
                dt = p.dt_fixed > 0 ? p.dt_fixed : dt_next;
                const double dtp = limitDt(physics::variableDt(forces(), h, cs0, cfl));
                if (midpoint) {
                    // Staggered midpoint: the solid goes to n+1/2 with the force of the fluid at n, so
                    // that the corrector's evaluation sees fluid and solid at n+1/2; then the solid
                    // restarts from n with that evaluation's force (below).
                    phase(t_solid, [&] {
                        backend_->solidHydroForces();
                        backend_->solidSave();
                        advanceSolid(t, 0.5 * dt, false);
                        return 0;
                    });
                }
                predictor(dt);
                divide(true);
                const double dtc = limitDt(physics::variableDt(forces(), h, cs0, cfl));
                if (solids) phase(t_solid, [&] { backend_->solidHydroForces(); return 0; });
                if (midpoint) phase(t_solid, [&] { backend_->solidRestore(); return 0; });
                corrector(dt);
                dt_next = std::min(dtp, dtc);
            } else {
                const double dtv = limitDt(physics::variableDt(forces(), h, cs0, cfl));
                dt = p.dt_fixed > 0 ? p.dt_fixed : dtv;
                const bool euler = ++verlet_count >= p.verlet_steps;
                if (euler) verlet_count = 0;
                if (solids) phase(t_solid, [&] { backend_->solidHydroForces(); return 0; });
                verlet(dt, euler);
                dt_prev = dt;
            }
            if (solids) phase(t_solid, [&] { advanceSolid(t, dt); return 0; });
            t += dt;
            ++step;
            // Moving boundaries: pose at t, velocity over the coming step (its dt when known).
            phase(t_other, [&] {
                placeMoving(t, symplectic ? (p.dt_fixed > 0 ? p.dt_fixed : dt_next) : dt_prev);
                return 0;
            });
            divide(false);
        }
        sum_.dt_last = dt;
        if (gauges_) gauges_->evaluate(t, *backend_);
        const std::uint32_t active = backend_->activeFluid();
        if (!warned_out && case_.nfluid > 0 &&
            double(case_.nfluid - active) > p.wrn_parts_out / 100.0 * case_.nfluid) {
            log_ << "warning: " << (case_.nfluid - active) << " fluid particles excluded (more than "
                 << p.wrn_parts_out << "% of the fluid)\n";
            warned_out = true;
        }
        if (t >= next_out - 1e-9 * tout || t >= tmax) {
            output(t, step);
            while (next_out <= t + 1e-9 * tout) next_out += tout;
        }
        if (p.min_fluid_stop > 0 && case_.nfluid > 0 && double(active) < p.min_fluid_stop * case_.nfluid) {
            sum_.stop_reason = "fluid below MinFluidStop";
            break;
        }
        const auto now = Clock::now();
        if (!opt_.quiet && opt_.progress_interval > 0 && seconds(t_progress, now) >= opt_.progress_interval) {
            t_progress = now;
            const double el = seconds(t_loop, now);
            const double sps = step / el;
            const double ns = el * 1e9 / (double(step) * double(sum_.np));
            const double eta = t > 0 ? el * (tmax - t) / t : 0;
            char line[256];
            std::snprintf(line, sizeof line,
                          "t=%.5f/%.4g s  steps=%lld  dt=%.3e  %.1f steps/s  %.2f ns/particle/step  "
                          "fluid=%u  dtmin-hits=%lld  ETA %.0f s\n",
                          t, tmax, step, dt, sps, ns, active, sum_.dtmin_hits, eta);
            log_ << line << std::flush;
        }
    }
    const auto t_end_loop = Clock::now();
    if (timers && step > 0) {
        char line[256];
        std::snprintf(line, sizeof line,
                      "phase times per step [ms]: divide %.3f  forces %.3f  integrate %.3f  motion %.3f  solid %.3f\n",
                      1e3 * t_divide / step, 1e3 * t_forces / step, 1e3 * t_integrate / step, 1e3 * t_other / step,
                      1e3 * t_solid / step);
        log_ << line;
    }
    if (out_index_ == 0 || sum_.outputs == 0) output(t, step);
    if (gauges_) {
        gauges_->flush();
        sum_.gauge_rows = gauges_->rows();
    }
    backend_->download(final_);
    sum_.state_hash = hashHex(stateHash(final_));
    for (std::uint8_t e : final_.excl) {
        if (e == physics::kExcludedPosition) ++sum_.excluded_position;
        if (e == physics::kExcludedDensity) ++sum_.excluded_density;
        if (e == physics::kExcludedNotFinite) ++sum_.excluded_not_finite;
    }
    sum_.fluid_active = backend_->activeFluid();
    sum_.steps = step;
    sum_.physical_time = t;
    sum_.loop_time = seconds(t_loop, t_end_loop);
    sum_.wall_time = seconds(t_start, Clock::now());
    sum_.ns_per_particle_step = step > 0 ? sum_.loop_time * 1e9 / (double(step) * double(sum_.np)) : 0;
    if (solids) {
        if (solid_only) {
            sum_.solid_substeps = step;  // each step is one solid sub-step
            sum_.omega_max = step > 0 ? 1 : 0;
        }
        sum_.solid_dt = setup_.solid.dt;
        sum_.broken_bonds = brokenBonds(final_);
        if (solid_only && step > 0)
            sum_.ns_per_particle_step = sum_.loop_time * 1e9 / (double(step) * double(setup_.solid.nsolid));
    }
    return sum_;
}

}  // namespace seaspring::solver
