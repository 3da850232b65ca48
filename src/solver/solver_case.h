// SeaSpring — MIT licence.
/// \file solver_case.h
/// \brief The case as the solver sees it: gencase's resolved OUTDIR/NAME.xml (constants,
///        parameters, domain, particle blocks, motion, solids summary) and OUTDIR/NAME.h5
///        (particles, bonds), read and checked against each other.
///
/// loadSolverCase is strict: anything seaspring does not implement stops the run with
/// "FILE:LINE: <element> ...: ... is not supported by seaspring (supported: ...)", and so do
/// unknown or repeated `<parameter>` keys, unknown elements, and any disagreement between
/// the XML and the particle file. Keys that have no effect in the chosen configuration
/// (SlipMode and NoPenetration with DBC, ShiftCoef and ShiftTFS without shifting) are
/// checked to be numbers and otherwise ignored, as DualSPHysics does.
/// The sections are read with the case model's readers (src/case); `<special><gauges>` with
/// model::readGauges; `<savedt>` is not evaluated (a note).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "case/case_constants.h"
#include "case/gauge_spec.h"
#include "case/mk_blocks.h"
#include "case/motion.h"
#include "case/parameters.h"
#include "case/solid_body.h"
#include "core/particle_set.h"
#include "core/vec3.h"

namespace seaspring::solver {

using model::MkBlock;
using model::SolidBody;
using model::SolverParameters;

/// The resolved case as the solver holds it (the case model's parts, see src/case).
struct SolverCase {
    std::string xml_path, h5_path;
    std::string name;  ///< case name: NAME of OUTDIR/NAME
    model::CaseConstants constants;
    SolverParameters params;
    Vec3d domain_min{0, 0, 0}, domain_max{0, 0, 0};  ///< <simulationdomain> (absolute) [m]
    std::vector<MkBlock> blocks;                     ///< in id order
    std::uint32_t nfixed = 0, nmoving = 0, nsolid = 0, nfluid = 0;
    model::MotionSet motion;           ///< empty when the case has none
    ParticleSet particles;             ///< id order
    std::optional<BondNetwork> bonds;  ///< only when the case has solids
    std::uint32_t solid_bodies = 0;    ///< <solid> entries of the resolved <vcpmsolids>
    std::vector<SolidBody> solids;     ///< the same entries, in file order
    model::GaugeSet gauges;            ///< <special><gauges> (empty when none)
    std::vector<std::string> notes;    ///< "FILE:LINE: ..." for sections read but not used
};

/// Loads and checks a case written by gencase. `path` is OUTDIR/NAME, OUTDIR/NAME.xml or
/// OUTDIR/NAME.h5; the particle file is the one named in `<files particles>` (relative to the
/// XML). Throws seaspring::Error naming the file, line and offending value.
SolverCase loadSolverCase(const std::string& path);

/// Printable lines (no trailing newline): particle counts by type, dp, h, c0, B, masses,
/// domain, motion and solids, and the notes.
std::vector<std::string> describeCase(const SolverCase& c);

}  // namespace seaspring::solver
