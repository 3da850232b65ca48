// SeaSpring — MIT licence.
/// \file forces.cpp
/// \brief `seaspring-post forces` (see forces.h).
#include "post/forces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

#include "core/error.h"
#include "core/particle_set.h"
#include "physics/fluid_pair_terms.h"
#include "physics/solid_coupling.h"
#include "post/part_series.h"
#include "post/sorted_block.h"
#include "solver/simulation.h"
#include "solver/solver_case.h"

namespace seaspring::post {

using physics::Double3;
using physics::Float2;
using physics::Float4;

struct ForceModel {
    std::string xml;                      ///< the case file, for messages
    std::size_t np = 0;
    io::PartConstants constants;          ///< what the part files must carry
    physics::KernelType kernel = physics::KernelType::Wendland;
    physics::Viscosity visco = physics::Viscosity::Artificial;
    int dim = 3;
    physics::FluidConstants c;
    physics::CellGrid grid;               ///< the run's, without skin
    std::vector<std::uint8_t> selected;   ///< by id: 1 = in the selection
    std::vector<std::uint32_t> ids;       ///< the selection, ascending
};

void ForceModelDeleter::operator()(ForceModel* m) const { delete m; }

namespace {

std::string listOf(const std::vector<int>& v) {
    std::string s;
    for (int x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
    return s;
}

/// The forces on the selected boundary slots of `s` (sorted: boundary block [0, nb), then the
/// fluid with cell starts `csf`), in slot order, by the in-run gauge's function.
template <class Opt>
void forcesOnSlots(const ForceModel& m, const SortedParticles& s, const std::vector<std::uint32_t>& csf,
                   std::uint32_t nb, std::vector<Double3>& by_id) {
    const std::size_t n = s.poscell.size();
    std::vector<Float4> velrho = s.velrho;
    std::vector<Float2> press_ovrho(n);
    physics::ParticleView v{};
    v.velrho = velrho.data();
    v.press_ovrho = press_ovrho.data();
    for (std::uint32_t i = 0; i < std::uint32_t(n); ++i) physics::pressureAt(i, v, m.c);  // as PressurePass
    physics::InteractionInputs in;
    in.poscell = s.poscell.data();
    in.velrho = velrho.data();
    in.cell_start_fluid = csf.data();
    in.press_ovrho = press_ovrho.data();
    in.tau = nullptr;   // no SPS (refused in makeForceModel)
    in.near = nullptr;  // visit every cell: the same pairs as the solver's exact near flags
    for (std::uint32_t i = 0; i < nb; ++i)
        if (m.selected[s.index[i]]) by_id[s.index[i]] = physics::hydroForceOnBoundary<Opt>(i, in, m.c, m.grid);
}

template <class Kernel, int kDim>
void dispatchVisco(const ForceModel& m, const SortedParticles& s, const std::vector<std::uint32_t>& csf,
                   std::uint32_t nb, std::vector<Double3>& by_id) {
    using physics::DensityDiffusion;
    using physics::FluidOptions;
    using physics::Viscosity;
    if (m.visco == Viscosity::Artificial)
        forcesOnSlots<FluidOptions<Kernel, Viscosity::Artificial, DensityDiffusion::None, kDim>>(m, s, csf, nb, by_id);
    else
        forcesOnSlots<FluidOptions<Kernel, Viscosity::Laminar, DensityDiffusion::None, kDim>>(m, s, csf, nb, by_id);
}

}  // namespace

std::unique_ptr<ForceModel, ForceModelDeleter> makeForceModel(const ForcesOptions& o, std::ostream& log) {
    if (o.filexml.empty()) throw Error("-filexml: the resolved case (NAME.xml written by gencase) is needed");
    if (o.onlymk.empty() == o.mkbound.empty()) throw Error("give either -onlymk (absolute MKs) or -mkbound (local numbers)");
    if (o.cell_div < 0 || o.cell_div > 5) throw Error("-celldiv must be 1..5 (5: -cellmode:dp; 0: as the run's -cellmode:auto)");
    solver::SolverCase k = solver::loadSolverCase(o.filexml);
    solver::SolverParameters& p = k.params;
    if (o.visco_treatment != 0) {
        if (!(o.visco >= 0)) throw Error("-viscoart/-viscolam: the viscosity must be >= 0");
        p.visco_treatment = o.visco_treatment;
        p.visco = o.visco;
    }
    if (o.visco_bound_factor >= 0) p.visco_bound_factor = o.visco_bound_factor;
    if (p.boundary == 2)
        throwInputError(k.xml_path, 0, "Boundary=2 (mDBC): seaspring-post forces does not support mDBC cases yet (the "
                                       "boundary's ghost-node state is not in the part files); use the in-run <force> gauge");
    if (p.visco_treatment == 2)
        throwInputError(k.xml_path, 0, "ViscoTreatment=2 (laminar+SPS): the SPS stress is not saved in the part files; "
                                       "use -viscolam:NU to compute the force with the laminar term only");
    const solver::BackendSetup s = solver::makeBackendSetup(k, o.cell_div, 0.0);
    auto m = std::unique_ptr<ForceModel, ForceModelDeleter>(new ForceModel);
    m->xml = k.xml_path;
    m->np = k.particles.size();
    m->constants = io::PartConstants{k.constants.h, k.constants.dp, p.kernel == 1 ? "cubic spline" : "Wendland C2",
                                     k.constants.rhop0, k.constants.dimensions, k.constants.b};
    m->kernel = s.physics.kernel;
    m->visco = s.physics.visco;
    m->dim = s.physics.dim;
    m->c = s.fluid;
    m->grid = s.grid;
    m->selected.assign(m->np, 0);
    std::vector<int> known;
    for (const model::MkBlock& b : k.blocks)
        if (b.type != ParticleType::Fluid) known.push_back(o.onlymk.empty() ? b.mk_local : b.mk);
    const std::vector<int>& want = o.onlymk.empty() ? o.mkbound : o.onlymk;
    for (int w : want) {
        bool found = false;
        for (const model::MkBlock& b : k.blocks) {
            if (b.type == ParticleType::Fluid || (o.onlymk.empty() ? b.mk_local : b.mk) != w) continue;
            found = true;
            for (std::uint32_t q = 0; q < b.count; ++q) m->selected[b.begin + q] = 1;
        }
        if (!found)
            throwInputError(k.xml_path, 0, std::string(o.onlymk.empty() ? "-mkbound:" : "-onlymk:") + std::to_string(w) +
                                               ": no boundary or solid particles with this " +
                                               (o.onlymk.empty() ? "mkbound" : "absolute MK") + " (the case has " +
                                               listOf(known) + ")");
    }
    for (std::uint32_t i = 0; i < m->np; ++i)
        if (m->selected[i]) m->ids.push_back(i);
    log << "forces: case " << k.xml_path << ", " << m->ids.size() << " boundary particle(s) selected, "
        << solver::describePhysics(p, k.constants.dimensions, s.grid.cell_div, 0.0) << "\n";
    return m;
}

Double3 forcesOfPart(const ForceModel& m, const io::PartData& d, const std::string& what) {
    const io::PartConstants& a = d.constants;
    const io::PartConstants& b = m.constants;
    auto mismatch = [&](const std::string& name, const std::string& part, const std::string& kase) {
        throw Error(what + ": " + name + " = " + part + " but the case " + m.xml + " has " + kase +
                    " (is -filexml this run's case?)");
    };
    auto num = [](double x) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", x);
        return std::string(buf);
    };
    if (d.np() != m.np) mismatch("np", std::to_string(d.np()), std::to_string(m.np));
    if (a.h != b.h) mismatch("h", num(a.h), num(b.h));
    if (a.dp != b.dp) mismatch("dp", num(a.dp), num(b.dp));
    if (a.kernel != b.kernel) mismatch("kernel", a.kernel, b.kernel);
    if (a.rhop0 != b.rhop0) mismatch("rhop0", num(a.rhop0), num(b.rhop0));
    if (a.dimension != b.dimension) mismatch("dimension", std::to_string(a.dimension), std::to_string(b.dimension));
    if (a.b != b.b) mismatch("b", num(a.b), num(b.b));
    std::vector<std::uint32_t> bound, fluid;
    for (std::uint32_t i = 0; i < std::uint32_t(d.np()); ++i) {
        if (d.type[i] != std::uint8_t(ParticleType::Fluid)) bound.push_back(i);
        else if (d.excluded[i] == 0) fluid.push_back(i);
    }
    for (std::uint32_t id : m.ids)
        if (d.type[id] == std::uint8_t(ParticleType::Fluid))
            throw Error(what + ": particle " + std::to_string(id) + " is fluid but a boundary particle in the case " + m.xml);
    SortedParticles s;
    appendSortedBlock(d, bound, m.grid, m.dim, s);
    const std::vector<std::uint32_t> csf = appendSortedBlock(d, fluid, m.grid, m.dim, s);
    std::vector<Double3> by_id(d.np(), Double3{0, 0, 0});
    const std::uint32_t nb = std::uint32_t(bound.size());
    const bool wendland = m.kernel == physics::KernelType::Wendland;
    if (wendland && m.dim == 2) dispatchVisco<physics::WendlandKernel, 2>(m, s, csf, nb, by_id);
    else if (wendland) dispatchVisco<physics::WendlandKernel, 3>(m, s, csf, nb, by_id);
    else if (m.dim == 2) dispatchVisco<physics::CubicKernel, 2>(m, s, csf, nb, by_id);
    else dispatchVisco<physics::CubicKernel, 3>(m, s, csf, nb, by_id);
    double fx = 0, fy = 0, fz = 0;  // in id order, as the gauge (GaugeSystem::evaluate)
    for (std::uint32_t id : m.ids) {
        fx += by_id[id].x;
        fy += by_id[id].y;
        fz += by_id[id].z;
    }
    return Double3{fx, fy, fz};
}

int runForces(const ForcesOptions& o, std::ostream& log) {
    const auto m = makeForceModel(o, log);
    const auto parts = listPartFiles(o.dirin, o.first, o.last);
    log << "forces: " << parts.size() << " part file(s) (" << parts.front().first << ".." << parts.back().first
        << ") in " << o.dirin << "\n";
    AtomicTextFile out(o.savecsv);
    std::FILE* f = out.file();
    std::fprintf(f, "part;time;forcex;forcey;forcez\n");
    int rows = 0;
    for (const auto& [idx, path] : parts) {
        const io::PartData d = io::readPartH5(path);
        const Double3 F = forcesOfPart(*m, d, path);
        std::fprintf(f, "%d;%.10g;%.9g;%.9g;%.9g\n", idx, d.time, F.x, F.y, F.z);
        ++rows;
    }
    out.commit();
    log << "forces: " << rows << " row(s) written to " << o.savecsv << "\n";
    return rows;
}

}  // namespace seaspring::post
