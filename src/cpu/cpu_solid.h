// SeaSpring — MIT licence.
/// \file cpu_solid.h
/// \brief OpenMP driver of the VCPM solids: the arrays (solid-index order) and the passes of a
///        sub-step over the shared functions of physics/vcpm.h.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/particle_updates.h"
#include "physics/vcpm.h"
#include "solver/backend.h"

namespace seaspring::cpu {

class CpuSolid {
public:
    void init(const solver::SolidSetup& s, const physics::StepConstants& step);
    bool empty() const { return n_ == 0; }
    std::uint32_t size() const { return n_; }

    /// slot[s] = sorted index of solid particle s, from the sorted ids of the boundary block.
    void updateSlots(const std::uint32_t* id, std::uint32_t nbound);
    const std::uint32_t* slots() const { return slot_.data(); }
    physics::Double3* fluidForce() { return fluid_force_.data(); }

    /// n sub-steps of dt (clamp nodes moved by `motions` over the whole interval).
    void steps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions);
    /// Positions and velocities into the boundary block (sorted arrays) after a sub-cycle of
    /// length dt; accumulates the coupling ledger (impulse and work of the hydrodynamic force).
    void toBoundary(double dt, bool ledger, physics::Double3* bpos, physics::Float4* bvelrho);
    void save();
    void restore();
    void download(solver::HostState& out) const;

private:
    physics::SolidState state();
    physics::SolidBonds bonds();
    physics::ClampNodes clamps();
    void evaluationSums(const physics::Double3* ep, double f);

    std::uint32_t n_ = 0, nclamp_ = 0, first_ = 0;
    physics::StepConstants step_;
    std::vector<std::uint8_t> count_, flags_, broken_;
    std::vector<std::uint32_t> partner_;
    std::vector<double> rest_;
    std::vector<std::uint16_t> body_;
    std::vector<physics::VcpmMaterial> materials_;
    std::vector<physics::Double3> pos_, pos_half_, vel_, vel0_, fluid_force_;
    std::vector<double> sum_;
    std::vector<physics::Double3> impulse_;  ///< ledger: sum of F dt per particle [N s]
    std::vector<double> work_;               ///< ledger: sum of F . dx per particle [J]
    std::vector<physics::Double3> pos_saved_, vel_saved_;
    std::vector<physics::Double3> load_force_, load_rate_;  ///< empty without point loads
    double t0_ = 0, span_ = 0;
    std::vector<std::uint8_t> broken_saved_;
    std::vector<std::uint32_t> slot_;
    std::vector<std::uint8_t> clamp_count_;
    std::vector<std::uint32_t> clamp_partner_, clamp_slot_;
    std::vector<physics::Double3> clamp_pos_initial_, clamp_start_, clamp_end_;
    std::vector<std::int16_t> clamp_object_;
    std::vector<double> clamp_sum_;
};

}  // namespace seaspring::cpu
