// SeaSpring — MIT licence.
/// \file solid_setup.h
/// \brief The VCPM solids of a case in the layout both backends use: bonds in padded,
///        slot-major arrays (physics::SolidBonds), clamp nodes with their reverse bond lists
///        (physics::ClampNodes), one material per body, and the solid time-step limit.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "physics/sph_types.h"
#include "physics/solid_contact.h"
#include "physics/vcpm.h"

namespace seaspring::solver {

struct SolverCase;

/// Host copy of everything the solid part of a backend is set up with (empty: no solids).
struct SolidSetup {
    int dim = 3;
    std::uint32_t first_solid = 0, nsolid = 0;
    int max_bonds = 0;                       ///< slots per particle (18 in 3D, 8 in 2D)
    std::vector<std::uint8_t> count;         ///< [nsolid] bonds of each particle
    std::vector<std::uint32_t> partner;      ///< [max_bonds * nsolid] slot-major
    std::vector<double> rest;                ///< rest lengths [m]
    std::vector<std::uint8_t> flags;         ///< physics::VcpmBondFlag
    std::vector<double> kfac;                ///< surface correction of each slot's stiffness (empty: none)
    std::vector<double> vw, vw_partner;      ///< volumetric weights of each slot and of its mirror (empty: none)
    /// The rows' bending (VcpmRowBending; empty: none): per axis a and side (0 -, 1 +), the slot
    /// of each particle's first-neighbour bond at (2a + side) * nsolid + r (physics::kNoRowSlot:
    /// none); row_axes 2 (x, z) in 2D, 3 in 3D.
    std::vector<std::uint8_t> row_slot;
    int row_axes = 0;
    std::vector<std::uint16_t> body;         ///< [nsolid] material index
    std::vector<physics::VcpmMaterial> materials;
    std::vector<double> poisson;             ///< the lattice's Poisson's ratio of each body (plane stress: nu')
    std::vector<double> lattice_young;       ///< the lattice's Young's modulus of each body (plane stress: E')
    std::vector<physics::Double3> pos, vel;  ///< initial state [nsolid]
    std::vector<double> mass;                ///< [nsolid] rho_S dp^D (reports)
    /// Point loads per particle, F = load_force + load_rate t (both empty without loads).
    std::vector<physics::Double3> load_force, load_rate;

    std::uint32_t nclamp = 0;
    int clamp_max = 0;                       ///< slots per clamp node
    std::vector<std::uint8_t> clamp_count;   ///< [nclamp]
    std::vector<std::uint32_t> clamp_partner, clamp_slot;  ///< [clamp_max * nclamp]
    std::vector<std::uint32_t> clamp_id;     ///< particle id of each clamp node
    std::vector<physics::Double3> clamp_pos; ///< initial position of each clamp node
    std::vector<std::int16_t> clamp_object;  ///< motion object moving it, -1 when fixed

    /// The simulation domain widened by 2h: a solid particle beyond it is frozen there (at rest,
    /// its bonds broken) and counted per body (physics::SolidKeepBox).
    physics::SolidKeepBox keep;
    /// Contact (VcpmContact 1; physics/solid_contact.h).
    bool contact_on = false;
    physics::ContactParams contact;
    std::uint32_t contact_cap = 0;  ///< candidates per particle
    double contact_dt = 0;          ///< its sub-step limit [s] (included in dt)
    double dt = 0;                 ///< solid sub-step: min over bodies of VcpmDtCoef dp / c_S (x the correction's factor) and contact_dt [s]
    std::vector<double> elastic_dt;  ///< per body, VcpmDtCoef dp / c_S [s]
    std::vector<double> dt_scale;    ///< per body, the surface correction's sub-step factor (solid_stability.h; 1 without it)
    std::uint64_t bonds = 0, clamp_bonds = 0;  ///< solid-solid pairs (once), clamp bonds
    std::vector<std::string> body_lines;       ///< one printable line per body

    bool empty() const { return nsolid == 0; }
};

/// Builds the solids of a case (id order; bonds from gencase's CSR network). Throws
/// seaspring::Error (file:line of the resolved case) when a solid particle's MK has no body.
SolidSetup makeSolidSetup(const SolverCase& c);

/// VcpmSurfaceCorrection: fills `kfac`, `vw` and `vw_partner` (physics/vcpm_surface.h) from
/// the bonds and the particles' initial positions, and scales each body's sub-step by the
/// corrected lattice's stability margin (solid_stability.h; `substep_bound`: VcpmSubStepBound).
void surfaceCorrection(SolidSetup& s, int substep_bound = 0);

/// VcpmRowBending: fills `row_slot` (each particle's first-neighbour bonds along each lattice
/// axis, from the rest vectors) and each body's k_r (physics/vcpm_rows.h).
void rowBending(SolidSetup& s, double dp);

/// The slot indices (slot-major) of the two bonds of solid particle r's row triplet along axis
/// a, false when it has none (VcpmRowBending off, or a side without a first-neighbour bond).
inline bool rowTripletSlots(const SolidSetup& s, std::uint32_t r, int a, std::size_t& km, std::size_t& kp) {
    if (s.row_slot.empty()) return false;
    const std::uint8_t qm = s.row_slot[std::size_t(2 * a) * s.nsolid + r];
    const std::uint8_t qp = s.row_slot[std::size_t(2 * a + 1) * s.nsolid + r];
    if (qm == physics::kNoRowSlot || qp == physics::kNoRowSlot) return false;
    km = std::size_t(qm) * s.nsolid + r;
    kp = std::size_t(qp) * s.nsolid + r;
    return true;
}

/// Broken-bond count of every solid particle (host, from the slot states).
std::vector<std::uint8_t> brokenPerParticle(const SolidSetup& s, const std::vector<std::uint8_t>& broken);

}  // namespace seaspring::solver
