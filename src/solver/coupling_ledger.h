// SeaSpring — MIT licence.
/// \file coupling_ledger.h
/// \brief OUTDIR/ledger.csv for cases with VCPM solids: at every output time, the momentum of
///        the fluid and of the solids, the hydrodynamic force on the solids and its time
///        integral, the work it has done on the solids, and the solids' kinetic, elastic and
///        gravitational energy. All sums are formed on the host in id order (deterministic).
#pragma once

#include <fstream>
#include <string>

#include "core/vec3.h"
#include "solver/backend.h"

namespace seaspring::solver {

struct LedgerRow {
    double time = 0;
    physics::Double3 fluid_momentum{0, 0, 0};  ///< sum m v over active fluid [kg m/s] (2D: per m)
    physics::Double3 solid_momentum{0, 0, 0};  ///< sum m_s v_s
    physics::Double3 fluid_force{0, 0, 0};     ///< hydrodynamic force on the solids now [N]
    physics::Double3 impulse{0, 0, 0};         ///< its time integral since t = 0 [N s]
    double work = 0;           ///< work of the hydrodynamic force on the solids [J]
    double kinetic = 0;        ///< solid kinetic energy [J]
    double elastic = 0;        ///< lattice energy U of the intact bonds [J]
    double potential = 0;      ///< solid gravitational energy relative to t = 0 [J]
    double fluid_kinetic = 0;  ///< fluid kinetic energy [J]
    physics::Double3 wall_force{0, 0, 0};  ///< hydrodynamic force on the fixed and moving walls now [N]
    bool contact = false;                      ///< contact on (VcpmContact): the two below are written
    physics::Double3 contact_impulse{0, 0, 0}; ///< time integral of the contact forces on the solids [N s]
    double contact_work = 0;                   ///< their work on the solids (springs and dashpots) [J]
};

/// The ledger row of a state (id order). `pos0`: initial positions (id order);
/// `fluid_mass`: mass of a fluid particle; `gravity`: g; `boundary_force`: the hydrodynamic
/// force on each boundary particle now (Backend::boundaryForces; the walls are the ids below
/// the first solid particle).
LedgerRow ledgerRow(double time, const HostState& st, const SolidSetup& so, const std::vector<Vec3d>& pos0,
                    std::uint32_t first_fluid, double fluid_mass, const physics::Double3& gravity,
                    const std::vector<physics::Double3>& boundary_force);

/// Appends rows to OUTDIR/ledger.csv (header on creation), separated by ';' as the gauge files
/// and DualSPHysics' CSV files are. With contact, four more columns: the contact forces'
/// impulse on the solids (solid-solid pairs cancel: it is what walls gave) and their work.
class LedgerFile {
public:
    /// `resume_offset` >= 0: a restarted run: the file is cut back to that many bytes (what it
    /// held at the checkpoint) and continued; a new file when it is not there.
    /// `contact`: with the contact columns.
    explicit LedgerFile(const std::string& outdir, long long resume_offset = -1, bool contact = false);
    void add(const LedgerRow& r);
    /// Bytes written so far (a restart file keeps it).
    long long offset() { return (long long)f_.tellp(); }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::ofstream f_;
};

}  // namespace seaspring::solver
