// SeaSpring — MIT licence.
/// \file pair_blocks.h
/// \brief Test scaffolding for the pair loops (test_pair_lanes.cpp, test_row_extents.cpp): the
///        particle arrays the pair loops read, the fluid constants of a small water case, and a
///        block of particles placed into the engine's layout (sorted by cell, stable, with
///        absolute cell starts).
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "physics/cell_grid.h"
#include "physics/fluid_constants.h"
#include "physics/fluid_pair_terms.h"

namespace seaspring::test {

/// Fluid and boundary blocks in the engine's layout (boundary block first), with what the pair
/// loops read of them.
struct PairBlocks {
    physics::CellGrid g;
    physics::FluidConstants c;
    std::uint32_t nb = 0, nf = 0;
    std::vector<physics::Float4> poscell, velrho;
    std::vector<physics::Float2> press_ovrho;
    std::vector<physics::SymTensor> tau;  ///< SPS stresses (empty where a test has none)
    std::vector<std::uint32_t> cs_bound, cs_fluid;

    physics::InteractionInputs inputs() const {
        physics::InteractionInputs in;
        in.poscell = poscell.data();
        in.velrho = velrho.data();
        in.cell_start_bound = cs_bound.data();
        in.cell_start_fluid = cs_fluid.data();
        in.tau = tau.empty() ? nullptr : tau.data();
        in.press_ovrho = press_ovrho.data();
        return in;
    }
};

/// Water at rho0 = 1000 with cs0 = 20 m/s, particle spacing dp and smoothing length h; `visco`
/// the artificial alpha (or a laminar nu), boundary factor 0.7, DDT 0.1, gravity -9.81 z.
inline physics::FluidConstants pairTestFluid(int dim, double dp, double h, double visco = 0.05) {
    const double rho0 = 1000;
    physics::FluidInputs fi;
    fi.h = h;
    fi.dp = dp;
    fi.dim = dim;
    fi.cs0 = 20;
    fi.b = 20.0 * 20.0 * rho0 / 7.0;
    fi.rhop0 = rho0;
    fi.massfluid = fi.massbound = rho0 * (dim == 3 ? dp * dp * dp : dp * dp);
    fi.visco = visco;
    fi.visco_bound_factor = 0.7;
    fi.ddt_value = 0.1;
    fi.gravity_z = -9.81;
    return physics::makeFluidConstants(fi);
}

/// Block particles k (PosCell pc[k] in linear cell cell[k], velrho vr[k]) stably sorted by cell
/// into poscell and velrho from `first`, and the block's cell starts (absolute indices, as the
/// engine's) into cs.
inline void placeSortedBlock(const physics::CellGrid& g, const std::vector<physics::Float4>& pc,
                             const std::vector<std::uint32_t>& cell, const std::vector<physics::Float4>& vr,
                             std::uint32_t first, std::vector<physics::Float4>& poscell,
                             std::vector<physics::Float4>& velrho, std::vector<std::uint32_t>& cs) {
    const std::uint32_t n = std::uint32_t(pc.size());
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return cell[a] < cell[b]; });
    const std::uint32_t nc = g.cellCount();
    cs.assign(nc + 1, 0);
    for (std::uint32_t k = 0; k < n; ++k) {
        poscell[first + k] = pc[order[k]];
        velrho[first + k] = vr[order[k]];
        ++cs[cell[order[k]] + 1];
    }
    for (std::uint32_t k = 0; k < nc; ++k) cs[k + 1] += cs[k];
    for (std::uint32_t k = 0; k <= nc; ++k) cs[k] += first;
}

}  // namespace seaspring::test
