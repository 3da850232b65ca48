// SeaSpring — MIT licence.
/// \file particle_extraction.cpp
#include "gencase/particle_extraction.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include <omp.h>

#include "core/error.h"
#include "core/memory_budget.h"
#include "physics/eos_tait.h"

namespace seaspring::gencase {

namespace {
/// gencase's memory per particle [bytes]: the ParticleSet (63), its lattice index (12), and the
/// HDF5 writer's and resolved-case builder's copies of the fields.
constexpr double kBytesPerParticle = 160;
}  // namespace

ParticleSet extractParticles(const LatticeGrid& grid, const MkTypes& types,
                             std::vector<Vec3i>* lattice) {
    const std::vector<std::uint16_t>& cells = grid.cells();
    const std::size_t nz = grid.nz(), plane = grid.nx() * grid.ny();
    const int nthreads = std::max(1, std::min<int>(omp_get_max_threads(), int(nz)));
    // Histogram of MKs per thread (each thread owns a contiguous range of z-planes).
    std::vector<std::vector<std::size_t>> hist(nthreads, std::vector<std::size_t>(65536, 0));
    auto zrange = [&](int t, std::size_t& z0, std::size_t& z1) {
        z0 = nz * t / nthreads;
        z1 = nz * (t + 1) / nthreads;
    };
#pragma omp parallel num_threads(nthreads)
    {
        const int t = omp_get_thread_num();
        std::size_t z0, z1;
        zrange(t, z0, z1);
        for (std::size_t c = z0 * plane; c < z1 * plane; ++c)
            if (cells[c]) ++hist[t][cells[c]];
    }
    // Key order: type block, then MK; inside a key, thread (z) order keeps lattice order.
    std::vector<int> mks;
    for (int mk = 1; mk < 65536; ++mk) {
        std::size_t n = 0;
        for (int t = 0; t < nthreads; ++t) n += hist[t][mk];
        if (n) mks.push_back(mk);
    }
    std::stable_sort(mks.begin(), mks.end(),
                     [&](int a, int b) { return types[a] < types[b]; });
    std::vector<std::vector<std::size_t>> start(nthreads, std::vector<std::size_t>(65536, 0));
    std::size_t total = 0;
    for (int mk : mks)
        for (int t = 0; t < nthreads; ++t) {
            start[t][mk] = total;
            total += hist[t][mk];
        }
    // The particles, their lattice indices, and the copies the writers make.
    const std::string memory = memoryProblem(std::to_string(total) + " particles", double(total) * kBytesPerParticle,
                                             "increase dp or reduce the drawn volume");
    if (!memory.empty()) throw Error(memory);
    ParticleSet p;
    p.resize(total);
    if (lattice) lattice->assign(total, Vec3i{0, 0, 0});
    const Vec3i lo = grid.lo();
#pragma omp parallel num_threads(nthreads)
    {
        const int t = omp_get_thread_num();
        std::size_t z0, z1;
        zrange(t, z0, z1);
        std::vector<std::size_t>& next = start[t];
        for (std::size_t z = z0; z < z1; ++z)
            for (std::size_t y = 0; y < grid.ny(); ++y)
                for (std::size_t x = 0; x < grid.nx(); ++x) {
                    const std::uint16_t mk = cells[(z * grid.ny() + y) * grid.nx() + x];
                    if (!mk) continue;
                    const std::size_t i = next[mk]++;
                    const int ix = lo.x + int(x), iy = lo.y + int(y), iz = lo.z + int(z);
                    p.id[i] = std::uint32_t(i);
                    p.type[i] = types[mk];
                    p.mk[i] = mk;
                    p.pos[i] = grid.position(ix, iy, iz);
                    p.vel[i] = {0.f, 0.f, 0.f};
                    p.rhop[i] = 0.f;
                    p.mass[i] = 0.f;
                    if (lattice) (*lattice)[i] = {ix, iy, iz};
                }
    }
    return p;
}

void setInitialDensity(ParticleSet& p, const LatticeGrid& grid, const std::vector<Vec3i>& lattice,
                       int rhopgradient, double rho0, double b, double gamma, double gz,
                       std::uint16_t fluid_mk_max) {
    const std::size_t n = p.size();
    const double g = std::fabs(gz);
    const bool hydrostatic = rhopgradient != 1 && g > 0 && b > 0;
    int zmax_fluid = INT_MIN;
    for (std::size_t i = 0; i < n; ++i)
        if (p.type[i] == ParticleType::Fluid) zmax_fluid = std::max(zmax_fluid, lattice[i].z);
    // rhopgradient 2: for every fluid site, the number of fluid sites above it in its
    // contiguous run (walk each column downwards once).
    std::vector<std::int32_t> sites_above;
    if (hydrostatic && rhopgradient == 2) {
        sites_above.assign(grid.cellCount(), 0);
        const std::vector<std::uint16_t>& cells = grid.cells();
        const std::size_t nx = grid.nx(), ny = grid.ny(), nz = grid.nz();
#pragma omp parallel for schedule(static)
        for (std::size_t col = 0; col < nx * ny; ++col) {
            std::int32_t run = -1;
            for (std::size_t z = nz; z-- > 0;) {
                const std::size_t c = z * nx * ny + col;
                const bool fluid = cells[c] != 0 && cells[c] <= fluid_mk_max;
                run = fluid ? run + 1 : -1;
                if (fluid) sites_above[c] = run;
            }
        }
    }
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        if (p.type[i] != ParticleType::Fluid || !hydrostatic) {
            p.rhop[i] = float(rho0);
            continue;
        }
        const Vec3i c = lattice[i];
        const double sites = rhopgradient == 2 ? double(sites_above[grid.linear(c.x, c.y, c.z)])
                                               : double(zmax_fluid - c.z);
        p.rhop[i] = float(physics::hydrostaticDensity(rho0, b, gamma, g, sites * grid.dp()));
    }
}

}  // namespace seaspring::gencase
