// SeaSpring — MIT licence.
/// \file case_builder.h
/// \brief gencase's pipeline: case definition XML → lattice → particles, constants, bonds,
///        motion and parameters, all validated before anything is written.
#pragma once

#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "case/gauge_spec.h"
#include "case/mk_blocks.h"
#include "case/parameters.h"
#include "case/xml_source.h"
#include "core/particle_set.h"
#include "gencase/boundary_normals.h"
#include "gencase/command_runner.h"
#include "gencase/constants.h"
#include "gencase/motion.h"
#include "gencase/particle_extraction.h"
#include "gencase/simulation_domain.h"
#include "gencase/vcpm_bonds.h"
#include "gencase/vcpm_solids.h"

namespace seaspring::gencase {

using model::GaugeKind;
using model::GaugeSet;
using model::GaugeSpec;
using model::MkBlock;
using model::XmlSource;

struct GencaseOptions {
    std::string definition;   ///< CASE_Def.xml (".xml" may be omitted, as with GenCase)
    std::string output_base;  ///< OUTDIR/NAME
    double dp_override = 0;   ///< -dp:VALUE (0: use the file's)
    bool save_vtk = false;    ///< -save:vtk
    bool verbose = false;
};

/// Everything gencase derives (the parts of the case model and what it takes to write them);
/// the resolved-case writer and the tests read it.
struct GeneratedCase {
    std::string name;
    MkConfig mkconfig;
    CaseConstants constants;
    ParticleSet particles;           ///< with the mDBC ghost vectors (`normal`) when <normals> is active
    std::vector<ShapeSet> shapes;    ///< shape sets named by <shapeout> (written as VTK files)
    std::string normals_set;         ///< shape set the normals come from ("" when none)
    GhostVectorStats normals_stats;
    std::vector<MkBlock> blocks;     ///< in id order
    std::vector<SolidBody> solids;   ///< `particles` filled once the bonds are built
    GaugeSet gauges;  ///< <special><gauges> (lengths resolved)
    BondNetwork bonds;
    BondStats bond_stats;
    MotionSet motion;
    DomainBox particle_box;
    DomainBox domain;
    model::ParameterValues parameters;  ///< resolved, table order
    std::size_t count(ParticleType t) const;
};

class CaseBuilder {
public:
    CaseBuilder(GencaseOptions options, std::ostream& log);
    ~CaseBuilder();

    /// Reads and validates the definition and generates everything in memory.
    const GeneratedCase& build();
    /// After build(): the solver's checks of the constants and the particle counts
    /// (case/case_checks.h: every constant finite, cflnumber in (0, 1], a speed of sound with
    /// fluid, fluid or solid particles at all), which the parameters already passed in build().
    /// gencase runs it before write(), so that it never writes a case the solver rejects; the
    /// geometry tests build cases without fluid and skip it. Throws seaspring::Error.
    void checkForSolver() const;
    /// Writes OUTDIR/NAME.xml, NAME.h5 (and NAME.vtu): temporary names first, renamed at the end.
    void write() const;

    const XmlSource& source() const { return *src_; }
    const GeneratedCase& result() const { return out_; }

private:
    void readHeader(pugi::xml_node casedef);
    void drawGeometry(pugi::xml_node geometry);
    void readExecution(pugi::xml_node execution);
    /// <special><gauges> (after finishParticles: needs h and the MK blocks).
    void readGauges(pugi::xml_node execution);
    MkTypes classifyMks() const;
    void checkMkUsage() const;
    void finishParticles();
    /// <normals>: the mDBC ghost vectors of the boundary particles (after finishParticles).
    void computeNormals(pugi::xml_node normals);
    void resolveParameters(pugi::xml_node parameters);
    void printSummary() const;

    GencaseOptions opt_;
    std::ostream& log_;
    std::unique_ptr<XmlSource> src_;
    ExpressionEvaluator ev_;
    ConstantsInput constants_in_;
    LatticeGrid grid_;
    std::vector<Vec3i> lattice_;
    GeneratedCase out_;
};

/// Throws seaspring::Error when OUTDIR/NAME names no file ("", "/", "dir/") or when one of the
/// outputs (NAME.xml, NAME.h5, NAME.vtu) would be the definition itself.
void checkOutputBase(const std::string& definition, const std::string& output_base);

/// Resolves "Case_Def" to "Case_Def.xml" when only the latter exists.
std::string resolveDefinitionPath(const std::string& path);

}  // namespace seaspring::gencase
