// SeaSpring — MIT licence.
/// \file solver_case.cpp
/// \brief Reading and checking the resolved case for the solver (see solver_case.h).
#include "solver/solver_case.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>

#include "case/case_checks.h"
#include "case/motion_xml.h"
#include "case/xml_source.h"
#include "core/error.h"
#include "core/format.h"
#include "io/case_h5.h"

namespace seaspring::solver {

namespace fs = std::filesystem;
using model::XmlSource;

namespace {

/// The particle file against the XML: counts, dimensions, dp, each particle's type and MK,
/// positions inside the domain.
void checkParticles(const XmlSource& src, pugi::xml_node parts,
                    const std::vector<pugi::xml_node>& block_nodes, pugi::xml_node constants,
                    pugi::xml_node dom, const SolverCase& c, const io::CaseFileContents& h5,
                    std::uint32_t np) {
    const std::string& f = c.h5_path;
    if (h5.particles.size() != np)
        src.fail(parts, "np=" + std::to_string(np) + " but " + f + " holds " +
                            std::to_string(h5.particles.size()) + " particles");
    if (h5.header.dimensions != c.constants.dimensions)
        throw Error(f + ": dimensions=" + std::to_string(h5.header.dimensions) + " but " +
                    src.where(constants.child("dimensions")) + " <dimensions> says " +
                    std::to_string(c.constants.dimensions));
    if (std::fabs(h5.header.dp - c.constants.dp) > 1e-12 * c.constants.dp)
        throw Error(f + ": dp=" + shortText(h5.header.dp) + " but " + src.where(constants.child("dp")) +
                    " <dp> says " + shortText(c.constants.dp));
    std::size_t b = 0;
    for (std::uint32_t i = 0; i < np; ++i) {
        while (i >= c.blocks[b].begin + c.blocks[b].count) ++b;  // the blocks cover 0..np-1
        const MkBlock& blk = c.blocks[b];
        if (h5.particles.type[i] != blk.type || h5.particles.mk[i] != blk.mk)
            throw Error(f + ": particle " + std::to_string(i) + " is " +
                        particleTypeName(h5.particles.type[i]) + " mk " +
                        std::to_string(h5.particles.mk[i]) + " but " + src.where(block_nodes[b]) +
                        " <" + particleTypeName(blk.type) + " mk=" + std::to_string(blk.mk) +
                        "> covers ids " + std::to_string(blk.begin) + ".." +
                        std::to_string(blk.begin + blk.count - 1));
        const Vec3d p = h5.particles.pos[i];
        if (!(p.x >= c.domain_min.x && p.x <= c.domain_max.x && p.y >= c.domain_min.y &&
              p.y <= c.domain_max.y && p.z >= c.domain_min.z && p.z <= c.domain_max.z))
            throw Error(f + ": particle " + std::to_string(i) + " at " + shortVec(p) + " lies outside " +
                        src.where(dom) + " <simulationdomain> " + shortVec(c.domain_min) + " - " +
                        shortVec(c.domain_max));
    }
}

/// The resolved <vcpmsolids> summary against the bonds of the particle file.
void checkSolids(const XmlSource& src, pugi::xml_node exec, SolverCase& c,
                 const io::CaseFileContents& h5) {
    const pugi::xml_node v = exec.child("vcpmsolids");
    if (c.nsolid == 0) {
        if (v) src.fail(v, "is present but <particles> has no solid block");
        if (h5.has_bonds)
            throw Error(c.h5_path + ": has bonds but the case has no solid particles");
        return;
    }
    if (!v)
        src.fail(exec.child("particles"),
                 "has solid particles but <execution> has no <vcpmsolids>");
    if (!h5.has_bonds)
        throw Error(c.h5_path + ": has no bonds but the case has " + std::to_string(c.nsolid) +
                    " solid particles");
    model::SolidTotals totals;
    c.solids = model::readSolids(src, v, c.blocks, totals);
    c.solid_bodies = std::uint32_t(c.solids.size());
    if (totals.particles != c.nsolid)
        src.fail(v, "particles=" + std::to_string(totals.particles) +
                        " but nsolid=" + std::to_string(c.nsolid));
    if (totals.bondslots != h5.bonds.bondSlots())
        src.fail(v, "bondslots=" + std::to_string(totals.bondslots) + " but " + c.h5_path + " holds " +
                        std::to_string(h5.bonds.bondSlots()) + " bond slots");
    if (h5.bonds.first_solid != c.nfixed + c.nmoving)
        throw Error(c.h5_path + ": bonds start at particle " +
                    std::to_string(h5.bonds.first_solid) + " but the solid block starts at " +
                    std::to_string(c.nfixed + c.nmoving));
    c.bonds = h5.bonds;
}

void readSpecial(const XmlSource& src, pugi::xml_node special, SolverCase& c) {
    for (pugi::xml_node n : special.children()) {
        if (XmlSource::isDisabled(n)) continue;
        const std::string name = n.name();
        if (name == "savedt")
            c.notes.push_back(src.where(n) + ": <" + name + "> is not evaluated by seaspring (ignored)");
        else if (name == "gauges")
            continue;  // read after the constants (loadSolverCase)
        else if (name != "vcpmsolids" && name != "flexstrucs")
            src.fail(
                n,
                "is not supported by seaspring (supported in <special>: vcpmsolids, flexstrucs, "
                "gauges and savedt, the last ignored)");
    }
}

std::string resolveXmlPath(const std::string& path) {
    const fs::path p(path);
    if (p.extension() == ".xml") return path;
    if (p.extension() == ".h5") return fs::path(p).replace_extension(".xml").string();
    return path + ".xml";
}

}  // namespace

SolverCase loadSolverCase(const std::string& path) {
    SolverCase c;
    c.xml_path = resolveXmlPath(path);
    if (!fs::is_regular_file(c.xml_path))
        throw Error(c.xml_path +
                    ": no such case file (give OUTDIR/NAME as written by `gencase CASE_Def.xml "
                    "OUTDIR/NAME`)");
    c.name = fs::path(c.xml_path).stem().string();
    const XmlSource src(c.xml_path);
    const pugi::xml_node root = src.root();
    if (std::string(root.name()) != "case") src.fail(root, "the root element must be <case>");
    src.checkChildren(root, {"casedef", "execution"});
    src.checkUnique(root, {"casedef", "execution"});
    const pugi::xml_node exec = src.child(root, "execution");
    const std::initializer_list<const char*> sections = {
        "special", "parameters", "constants", "particles", "motion", "vcpmsolids", "files"};
    src.checkChildren(exec, sections);
    src.checkUnique(exec, sections);
    if (pugi::xml_node sp = exec.child("special")) readSpecial(src, sp, c);

    const pugi::xml_node parts = src.child(exec, "particles");
    std::vector<pugi::xml_node> block_nodes;
    model::ParticleBlocks pb = model::readParticleBlocks(src, parts, &block_nodes);
    const std::uint32_t np = pb.np;
    c.blocks = std::move(pb.blocks);
    c.nfixed = pb.nfixed;
    c.nmoving = pb.nmoving;
    c.nsolid = pb.nsolid;
    c.nfluid = pb.nfluid;
    const pugi::xml_node constants = src.child(exec, "constants");
    c.constants = model::readConstants(src, constants);
    model::checkCaseConstants(src, constants, constants, c.constants, c.nfluid > 0, c.nfixed + c.nmoving > 0);

    if (pugi::xml_node g = exec.child("special").child("gauges"); g && !XmlSource::isDisabled(g))
        c.gauges = model::readGauges(src, g, c.constants.dp, c.constants.h);

    const pugi::xml_node params = src.child(exec, "parameters");
    c.params = model::readSolverParameters(src, params, c.nfluid > 0);
    c.params.cfl_number = c.constants.cflnumber;
    const model::DomainBox domain = model::readSimulationDomain(src, params, c.constants.dimensions);
    c.domain_min = domain.min;
    c.domain_max = domain.max;

    if (pugi::xml_node m = exec.child("motion")) c.motion = model::readMotion(src, m);
    for (std::size_t b = 0; b < c.blocks.size(); ++b)
        if (c.blocks[b].type == ParticleType::Moving && !c.motion.find(c.blocks[b].mk_local))
            src.fail(block_nodes[b], "mkbound=" + std::to_string(c.blocks[b].mk_local) +
                                         " is a moving boundary without <objreal ref=\"" +
                                         std::to_string(c.blocks[b].mk_local) + "\"> in <motion>");

    const pugi::xml_node files = src.child(exec, "files");
    src.checkAttributes(files, {"particles"});
    const std::string h5_name = src.text(files, "particles");
    c.h5_path = (fs::path(src.directory()) / h5_name).string();
    if (!fs::is_regular_file(c.h5_path))
        src.fail(files, "particles=\"" + h5_name + "\": " + c.h5_path +
                            " does not exist (run gencase again)");
    io::CaseFileContents h5 = io::readCaseH5(c.h5_path);
    checkParticles(src, parts, block_nodes, constants, params.child("simulationdomain"), c, h5, np);
    checkSolids(src, exec, c, h5);
    model::checkCaseHasWork(src, parts, c.nfluid, c.nsolid);
    c.particles = std::move(h5.particles);
    return c;
}

std::vector<std::string> describeCase(const SolverCase& c) {
    const model::CaseConstants& k = c.constants;
    std::vector<std::string> out;
    out.push_back("particles: " + std::to_string(c.particles.size()) + " (fixed " +
                  std::to_string(c.nfixed) + ", moving " + std::to_string(c.nmoving) + ", solid " +
                  std::to_string(c.nsolid) + ", fluid " + std::to_string(c.nfluid) + "), " +
                  std::to_string(k.dimensions) + "D");
    out.push_back("dp=" + shortText(k.dp) + " m, h=" + shortText(k.h) + " m, c0=" + shortText(k.speedsound) +
                  " m/s, B=" + shortText(k.b) + " Pa, rho0=" + shortText(k.rhop0) +
                  " kg/m^3, gamma=" + shortText(k.gamma));
    out.push_back("mass: fluid " + shortText(k.massfluid) + " kg, boundary " + shortText(k.massbound) + " kg");
    out.push_back("domain: " + shortVec(c.domain_min) + " - " + shortVec(c.domain_max) + " m");
    if (!c.motion.empty())
        out.push_back("motion: " + std::to_string(c.motion.objects.size()) + " object(s)");
    if (c.bonds)
        out.push_back("VCPM solids: " + std::to_string(c.solid_bodies) + " bod" +
                      (c.solid_bodies == 1 ? "y" : "ies") + ", " +
                      std::to_string(c.bonds->bondSlots()) + " bond slots");
    for (const std::string& n : c.notes) out.push_back("note: " + n);
    return out;
}

}  // namespace seaspring::solver
