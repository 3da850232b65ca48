// SeaSpring — MIT licence.
/// \file solid_body.h
/// \brief VCPM lattice solids: the boundary MKs modelled as solids, their material, clamps
///        and point loads (gencase reads them from `<special><vcpmsolids|flexstrucs>`, the
///        resolved case holds them in `<execution><vcpmsolids>`, read back by the solver).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "case/mk_blocks.h"
#include "case/xml_source.h"
#include "core/vec3.h"

namespace seaspring::model {

/// `<pointload>`: a concentrated force on the solid particle nearest to `point` (initial
/// configuration): F(t) = force + rate * t [N] (2D: N per m of thickness).
struct PointLoad {
    Vec3d point{0, 0, 0}, force{0, 0, 0}, rate{0, 0, 0};
    int line = 0;
};

/// One solid body: a boundary MK modelled as a VCPM lattice solid.
struct SolidBody {
    using Load = PointLoad;
    int mkbound = 0;
    std::uint16_t mk = 0;                 ///< global MK of its particles
    std::vector<int> clamp_mkbound;       ///< mkbound of its clamp boundaries
    std::vector<std::uint16_t> clamp_mk;  ///< global MKs of its clamp boundaries
    double density = 0;                   ///< rho_S [kg/m^3]
    double youngmod = 0;                  ///< E [Pa]
    double poissratio = 0;                ///< nu, in (-1, 0.5)
    /// DualSPHysics' constitmodel: 1 plane strain (2D), 2 plane stress (2D), 3 three-dimensional
    /// (DualSPHysics' St Venant-Kirchhoff; here the 3D lattice); 0 when not given: the case's
    /// dimension decides (1 in 2D, 3 in 3D).
    int constitmodel = 0;
    double critstretch = 0;               ///< bond breaks at elongation/rest length > this; 0: never
    double damping = 0;                   ///< multiplies sqrt(E/(rho dp^2)); 0: no damping
    std::vector<PointLoad> loads;         ///< <pointload> children
    std::string declared_in;              ///< "vcpmsolids" or "flexstrucs" (DualSPHysics' bodies)
    std::uint64_t particles = 0;          ///< particles of its MK (known once they are generated)
    int line = 0;                         ///< line of its element in the file it was read from
};

/// The constitutive model of a body in a case of `dim` dimensions (constitmodel, or 1 in 2D
/// and 3 in 3D when it is 0).
int effectiveConstitModel(const SolidBody& s, int dim);
/// "" when `constitmodel` (0..3) fits a case of `dim` dimensions, else why not.
std::string constitModelProblem(int constitmodel, int dim);

/// Totals of the resolved `<vcpmsolids>` (gencase's bond statistics). The solver reads back
/// `particles` and `bondslots` only; the others are for the reader of the file.
struct SolidTotals {
    std::uint64_t particles = 0, bonds = 0, clampbonds = 0, surface = 0, bondslots = 0;
};

/// Appends the resolved `<vcpmsolids>` (totals, then one `<solid>` per body with its
/// `<pointload>` children, plain numbers) to `parent`.
void writeSolids(pugi::xml_node parent, const std::vector<SolidBody>& solids, const SolidTotals& totals);

/// Reads the resolved `<vcpmsolids>` and checks each body's values; the clamps are looked up
/// among the fixed and moving `blocks`. Fills `totals.particles` and `totals.bondslots`.
std::vector<SolidBody> readSolids(const XmlSource& src, pugi::xml_node vcpmsolids,
                                  const std::vector<MkBlock>& blocks, SolidTotals& totals);

}  // namespace seaspring::model
