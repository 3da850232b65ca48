// SeaSpring — MIT licence.
/// \file solver_case.cpp
/// \brief Reading and checking the resolved case for the solver (see solver_case.h).
#include "solver/solver_case.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <set>

#include "core/case_parameters.h"
#include "core/error.h"
#include "gencase/xml_source.h"
#include "io/case_h5.h"

namespace seaspring::solver {

namespace fs = std::filesystem;
using gencase::XmlSource;

namespace {

std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string vec(Vec3d v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }

/// The `<parameter key value>` entries of `<parameters>`, checked against the key table.
/// Keys that are absent take the table's default (a required one that is absent is an error).
class ParameterTable {
public:
    ParameterTable(const XmlSource& src, pugi::xml_node params, bool has_fluid)
        : src_(src), params_(params) {
        src.checkChildren(params, {"parameter", "simulationdomain"});
        for (pugi::xml_node n : params.children("parameter")) {
            src.checkAttributes(n, {"key", "value"});
            const std::string key = src.text(n, "key");
            if (!key.empty() && key[0] == '#') continue;  // commented out (DualSPHysics habit)
            const ParameterInfo* info = findParameter(key);
            if (!info)
                src.fail(n,
                         "key=\"" + key + "\" is not a known parameter (see docs/case-format.md)");
            if (info->kind == ParameterKind::Deprecated)
                src.fail(n, "key=\"" + key +
                                "\" is deprecated and not written by gencase; regenerate the case");
            if (given_.count(key)) src.fail(n, "key=\"" + key + "\" is given twice");
            given_[key] = n;
        }
        for (const ParameterInfo& info : knownParameters()) {
            const bool needed =
                !info.default_value && (std::string(info.key) != "Visco" || has_fluid);
            if (needed && !given_.count(info.key))
                src.fail(params, std::string("misses the required parameter ") + info.key + " (" +
                                     info.meaning + ")");
        }
    }

    /// The value as written, or the default ("" for an absent required key).
    std::string text(const std::string& key) const {
        const auto it = given_.find(key);
        if (it != given_.end()) return it->second.attribute("value").value();
        const ParameterInfo* info = findParameter(key);
        return info && info->default_value ? info->default_value : "";
    }
    double number(const std::string& key) const {
        const std::string t = text(key);
        if (t.empty() && !given_.count(key))
            return 0;  // optional-required key (Visco without fluid)
        try {
            return gencase::parseNumber(t);
        } catch (const std::exception& e) {
            fail(key, e.what());
        }
    }
    int integer(const std::string& key) const {
        const double v = number(key);
        if (v != std::floor(v) || std::fabs(v) > 1e9) fail(key, "expected an integer");
        return int(v);
    }
    /// One of `allowed`, else "not supported by seaspring (supported: ...)".
    int choice(const std::string& key, std::initializer_list<int> allowed,
               const std::string& supported, const std::string& what = "") const {
        const int v = integer(key);
        for (int a : allowed)
            if (v == a) return v;
        fail(key, (what.empty() ? "" : what + " ") +
                      "is not supported by seaspring (supported: " + supported + ")");
    }
    /// The key must keep the value that switches its feature off.
    void requireOff(const std::string& key, double off, const std::string& feature) const {
        if (number(key) != off)
            fail(key,
                 feature + " is not supported by seaspring (supported: " + num(off) + ", off)");
    }
    void requireNone(const std::string& key, const std::string& feature) const {
        const std::string t = text(key);
        if (t != "NONE" && !t.empty())
            fail(key, feature + " is not supported by seaspring (supported: NONE)");
    }
    double atLeast(const std::string& key, double lo, bool inclusive) const {
        const double v = number(key);
        if (inclusive ? !(v >= lo) : !(v > lo))
            fail(key, std::string("must be ") + (inclusive ? ">= " : "> ") + num(lo));
        return v;
    }
    /// "FILE:LINE: <parameter> key="K" value="V": message" (the line of <parameters> when absent).
    [[noreturn]] void fail(const std::string& key, const std::string& message) const {
        const auto it = given_.find(key);
        const pugi::xml_node n = it != given_.end() ? it->second : params_;
        src_.fail(n, "key=\"" + key + "\" value=\"" + text(key) + "\"" +
                         (it == given_.end() ? " (default)" : "") + ": " + message);
    }

private:
    const XmlSource& src_;
    pugi::xml_node params_;
    std::map<std::string, pugi::xml_node> given_;
};

SolverParameters readParameters(const ParameterTable& t) {
    SolverParameters p;
    t.number("SavePosDouble");  // positions are always double in seaspring
    t.choice("Boundary", {1}, "1 DBC", "mDBC");
    t.number("SlipMode");       // mDBC only
    t.number("NoPenetration");  // mDBC only
    p.step_algorithm = t.choice("StepAlgorithm", {1, 2}, "1 Verlet, 2 symplectic");
    p.verlet_steps = t.integer("VerletSteps");
    if (p.verlet_steps < 1) t.fail("VerletSteps", "must be >= 1");
    p.kernel = t.choice("Kernel", {1, 2}, "1 cubic spline, 2 Wendland");
    p.visco_treatment =
        t.choice("ViscoTreatment", {1, 2, 3}, "1 artificial, 2 laminar+SPS, 3 laminar");
    p.visco = t.atLeast("Visco", 0, true);
    p.visco_bound_factor = t.atLeast("ViscoBoundFactor", 0, true);
    t.requireNone("ViscoTime", "a viscosity-time file");
    p.density_dt =
        t.choice("DensityDT", {0, 1, 2, 3}, "0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full");
    p.density_dt_value = t.atLeast("DensityDTvalue", 0, true);
    t.choice("Shifting", {0}, "0 none", "particle shifting");
    t.number("ShiftCoef");  // shifting only
    t.number("ShiftTFS");   // shifting only
    t.choice("RigidAlgorithm", {1}, "1, the default; floating bodies are not supported",
             "a floating-body algorithm");
    t.requireOff("FtPause", 0, "a floating-body pause");
    t.requireOff("FtIgnoreRadius", 0, "the floating-body radius option");
    p.coef_dt_min = t.atLeast("CoefDtMin", 0, false);
    p.dt_ini = t.atLeast("DtIni", 0, true);
    p.dt_min = t.atLeast("DtMin", 0, true);
    p.dt_fixed = t.atLeast("DtFixed", 0, true);
    t.requireNone("DtFixedFile", "a dt file");
    p.dt_all_particles = t.choice("DtAllParticles", {0, 1}, "0 fluid, 1 all particles") != 0;
    p.time_max = t.atLeast("TimeMax", 0, false);
    p.vcpm_dt_coef = t.atLeast("VcpmDtCoef", 0, false);
    p.vcpm_coupling = t.choice("VcpmCoupling", {1, 2}, "1 staggered as seed 000, 2 staggered midpoint");
    if (p.vcpm_dt_coef > 2) t.fail("VcpmDtCoef", "must be <= 2 (the lattice is unstable far below that; 0.8 is safe for nu >= 0)");
    p.time_out = t.atLeast("TimeOut", 0, false);
    if (t.number("TimeOutExtra") > 0)
        t.fail("TimeOutExtra",
               "extra motion output is not supported by seaspring (supported: <= 0, off)");
    p.rhop_out_min = t.atLeast("RhopOutMin", 0, true);
    p.rhop_out_max = t.number("RhopOutMax");
    if (!(p.rhop_out_max > p.rhop_out_min))
        t.fail("RhopOutMax", "must exceed RhopOutMin=" + t.text("RhopOutMin"));
    p.min_fluid_stop = t.atLeast("MinFluidStop", 0, true);
    if (p.min_fluid_stop > 1) t.fail("MinFluidStop", "is a fraction of the fluid: must be <= 1");
    p.wrn_parts_out = t.atLeast("WrnPartsOut", 0, true);
    for (const char* k :
         {"XPeriodicIncY", "XPeriodicIncZ", "YPeriodicIncX", "YPeriodicIncZ", "ZPeriodicIncX",
          "ZPeriodicIncY", "XYPeriodic", "XZPeriodic", "YZPeriodic"})
        t.requireOff(k, 0, "periodic boundaries");
    t.requireOff("Symmetry", 0, "a symmetry plane");
    t.requireOff("DivCleanKp", 0, "divergence cleaning");
    return p;
}

void checkConstants(const XmlSource& src, pugi::xml_node node, const gencase::CaseConstants& c,
                    bool has_fluid, bool has_boundary) {
    auto bad = [&](const char* name, double v, const std::string& why) {
        src.fail(node.child(name), "value=" + num(v) + ": " + why);
    };
    if (c.dimensions != 2 && c.dimensions != 3) bad("dimensions", c.dimensions, "must be 2 or 3");
    if (!(c.dp > 0)) bad("dp", c.dp, "must be > 0");
    if (!(c.h > 0)) bad("h", c.h, "must be > 0");
    if (!(c.speedsound > 0)) bad("speedsound", c.speedsound, "must be > 0");
    if (!(c.b > 0)) bad("b", c.b, "must be > 0");
    if (!(c.rhop0 > 0)) bad("rhop0", c.rhop0, "must be > 0");
    if (c.gamma != 7) bad("gamma", c.gamma, "is not supported by seaspring (supported: 7)");
    if (!(c.cflnumber > 0 && c.cflnumber <= 1)) bad("cflnumber", c.cflnumber, "must lie in (0, 1]");
    if (has_fluid && !(c.massfluid > 0)) bad("massfluid", c.massfluid, "must be > 0");
    if (has_boundary && !(c.massbound > 0)) bad("massbound", c.massbound, "must be > 0");
}

/// A non-negative integer attribute written as plain digits.
std::uint32_t count(const XmlSource& src, pugi::xml_node n, const char* attr,
                    std::uint32_t max = 0xffffffffu) {
    const std::string t = src.text(n, attr);
    char* end = nullptr;
    const unsigned long long v = std::strtoull(t.c_str(), &end, 10);
    if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || *end || v > max)
        src.fail(n, std::string("attribute ") + attr + "=\"" + t +
                        "\": expected an integer in 0.." + std::to_string(max));
    return std::uint32_t(v);
}

ParticleType blockType(const XmlSource& src, pugi::xml_node n) {
    const std::string name = n.name();
    for (ParticleType t :
         {ParticleType::Fixed, ParticleType::Moving, ParticleType::Solid, ParticleType::Fluid})
        if (name == particleTypeName(t)) return t;
    src.fail(n, "is not a particle block (expected fixed, moving, solid or fluid)");
}

/// Reads <particles> into c.blocks and the counts; returns the block elements (same order).
std::vector<pugi::xml_node> readBlocks(const XmlSource& src, pugi::xml_node parts, SolverCase& c,
                                       std::uint32_t& np) {
    std::vector<pugi::xml_node> nodes;
    src.checkAttributes(
        parts, {"np", "nfixed", "nmoving", "nsolid", "nfluid", "mkboundfirst", "mkfluidfirst"});
    np = count(src, parts, "np");
    c.nfixed = count(src, parts, "nfixed");
    c.nmoving = count(src, parts, "nmoving");
    c.nsolid = count(src, parts, "nsolid");
    c.nfluid = count(src, parts, "nfluid");
    if (std::uint64_t(c.nfixed) + c.nmoving + c.nsolid + c.nfluid != np)
        src.fail(parts,
                 "np=" + std::to_string(np) + " differs from nfixed+nmoving+nsolid+nfluid=" +
                     std::to_string(std::uint64_t(c.nfixed) + c.nmoving + c.nsolid + c.nfluid));
    std::uint64_t next = 0, by_type[4] = {0, 0, 0, 0};
    std::set<int> mks;
    for (pugi::xml_node n : parts.children()) {
        if (n.type() != pugi::node_element) continue;
        MkBlock b;
        b.type = blockType(src, n);
        const char* local = b.type == ParticleType::Fluid ? "mkfluid" : "mkbound";
        src.checkAttributes(n, {"mk", local, "begin", "count"});
        b.mk = int(count(src, n, "mk", 65535));
        b.mk_local = int(count(src, n, local, 65535));
        b.begin = count(src, n, "begin");
        b.count = count(src, n, "count");
        if (b.begin != next)
            src.fail(n, "begin=" + std::to_string(b.begin) +
                            ": blocks must follow each other (expected " + std::to_string(next) +
                            ")");
        if (!c.blocks.empty() && b.type < c.blocks.back().type)
            src.fail(n, "comes after a " + std::string(particleTypeName(c.blocks.back().type)) +
                            " block (order: fixed, moving, solid, fluid)");
        if (!mks.insert(b.mk).second)
            src.fail(n, "mk=" + std::to_string(b.mk) + " has a second block");
        next += b.count;
        by_type[int(b.type)] += b.count;
        c.blocks.push_back(b);
        nodes.push_back(n);
    }
    if (next != np)
        src.fail(parts, "np=" + std::to_string(np) + " but its blocks hold " +
                            std::to_string(next) + " particles");
    const std::uint32_t declared[4] = {c.nfixed, c.nmoving, c.nsolid, c.nfluid};
    for (int t = 0; t < 4; ++t)
        if (by_type[t] != declared[t])
            src.fail(parts, std::string("n") + particleTypeName(ParticleType(t)) + "=" +
                                std::to_string(declared[t]) + " but its " +
                                particleTypeName(ParticleType(t)) + " blocks hold " +
                                std::to_string(by_type[t]) + " particles");
    return nodes;
}

void readDomain(const XmlSource& src, pugi::xml_node params, SolverCase& c) {
    src.checkUnique(params, {"simulationdomain"});
    const pugi::xml_node dom = src.child(params, "simulationdomain");
    src.checkChildren(dom, {"posmin", "posmax"});
    const gencase::ExpressionEvaluator ev;
    c.domain_min = src.vec3(src.child(dom, "posmin"), ev);
    c.domain_max = src.vec3(src.child(dom, "posmax"), ev);
    const double lo[3] = {c.domain_min.x, c.domain_min.y, c.domain_min.z};
    const double hi[3] = {c.domain_max.x, c.domain_max.y, c.domain_max.z};
    for (int k = 0; k < 3; ++k) {
        const bool flat_ok = k == 1 && c.constants.dimensions == 2;
        if (flat_ok ? !(lo[k] <= hi[k]) : !(lo[k] < hi[k]))
            src.fail(dom, "posmin " + vec(c.domain_min) + " must lie below posmax " +
                              vec(c.domain_max) + " in " + "xyz"[k]);
    }
}

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
        throw Error(f + ": dp=" + num(h5.header.dp) + " but " + src.where(constants.child("dp")) +
                    " <dp> says " + num(c.constants.dp));
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
            throw Error(f + ": particle " + std::to_string(i) + " at " + vec(p) + " lies outside " +
                        src.where(dom) + " <simulationdomain> " + vec(c.domain_min) + " - " +
                        vec(c.domain_max));
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
    src.checkChildren(v, {"solid"});
    const std::uint32_t particles = count(src, v, "particles"), slots = count(src, v, "bondslots");
    if (particles != c.nsolid)
        src.fail(v, "particles=" + std::to_string(particles) +
                        " but nsolid=" + std::to_string(c.nsolid));
    if (slots != h5.bonds.bondSlots())
        src.fail(v, "bondslots=" + std::to_string(slots) + " but " + c.h5_path + " holds " +
                        std::to_string(h5.bonds.bondSlots()) + " bond slots");
    if (h5.bonds.first_solid != c.nfixed + c.nmoving)
        throw Error(c.h5_path + ": bonds start at particle " +
                    std::to_string(h5.bonds.first_solid) + " but the solid block starts at " +
                    std::to_string(c.nfixed + c.nmoving));
    for (pugi::xml_node s : v.children("solid")) {
        src.checkAttributes(s, {"mkbound", "mk", "mkclamp", "density", "youngmod", "poissratio",
                                "critstretch", "damping", "declaredin", "particles"});
        SolidBody b;
        b.line = src.lineOf(s);
        auto number = [&](const char* attr) {
            try {
                return gencase::parseNumber(src.text(s, attr));
            } catch (const std::exception& e) {
                src.fail(s, std::string(attr) + "=\"" + s.attribute(attr).value() + "\": " + e.what());
            }
        };
        b.mkbound = int(count(src, s, "mkbound", 65535));
        b.mk = std::uint16_t(count(src, s, "mk", 65535));
        b.density = number("density");
        b.youngmod = number("youngmod");
        b.poissratio = number("poissratio");
        b.critstretch = number("critstretch");
        b.damping = number("damping");
        if (!(b.density > 0)) src.fail(s, "density=\"" + num(b.density) + "\": must be > 0 [kg/m^3]");
        if (!(b.youngmod > 0)) src.fail(s, "youngmod=\"" + num(b.youngmod) + "\": must be > 0 [Pa]");
        if (!(b.poissratio > -1 && b.poissratio < 0.5))
            src.fail(s, "poissratio=\"" + num(b.poissratio) + "\": must lie in (-1, 0.5)");
        if (!(b.critstretch >= 0)) src.fail(s, "critstretch=\"" + num(b.critstretch) + "\": must be >= 0");
        if (!(b.damping >= 0)) src.fail(s, "damping=\"" + num(b.damping) + "\": must be >= 0");
        src.checkChildren(s, {"pointload"});
        for (pugi::xml_node l : s.children("pointload")) {
            src.checkAttributes(l, {"x", "y", "z", "fx", "fy", "fz", "ratex", "ratey", "ratez"});
            auto lnum = [&](const char* attr) {
                try {
                    return gencase::parseNumber(src.text(l, attr));
                } catch (const std::exception& e) {
                    src.fail(l, std::string(attr) + "=\"" + l.attribute(attr).value() + "\": " + e.what());
                }
            };
            SolidBody::Load load;
            load.line = src.lineOf(l);
            load.point = Vec3d{lnum("x"), lnum("y"), lnum("z")};
            load.force = Vec3d{lnum("fx"), lnum("fy"), lnum("fz")};
            load.rate = Vec3d{lnum("ratex"), lnum("ratey"), lnum("ratez")};
            b.loads.push_back(load);
        }
        const std::string clamps = s.attribute("mkclamp").value();
        std::size_t from = 0;
        while (from < clamps.size()) {
            const std::size_t comma = clamps.find(',', from);
            const std::string item = clamps.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
            char* end = nullptr;
            const long mkb = std::strtol(item.c_str(), &end, 10);
            if (item.empty() || *end != '\0' || mkb < 0)
                src.fail(s, "mkclamp=\"" + clamps + "\": expected mkbound numbers separated by commas");
            bool found = false;
            for (const MkBlock& blk : c.blocks)
                if ((blk.type == ParticleType::Fixed || blk.type == ParticleType::Moving) && blk.mk_local == mkb) {
                    b.clamp_mk.push_back(std::uint16_t(blk.mk));
                    found = true;
                }
            if (!found)
                src.fail(s, "mkclamp=\"" + clamps + "\": mkbound " + item + " has no fixed or moving particle block");
            if (comma == std::string::npos) break;
            from = comma + 1;
        }
        c.solids.push_back(b);
        ++c.solid_bodies;
    }
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
    std::uint32_t np = 0;
    const std::vector<pugi::xml_node> block_nodes = readBlocks(src, parts, c, np);
    const pugi::xml_node constants = src.child(exec, "constants");
    c.constants = gencase::readConstants(src, constants);
    checkConstants(src, constants, c.constants, c.nfluid > 0, c.nfixed + c.nmoving > 0);

    if (pugi::xml_node g = exec.child("special").child("gauges"); g && !XmlSource::isDisabled(g))
        c.gauges = gencase::parseGauges(src, g, gencase::ExpressionEvaluator{}, c.constants.dp, c.constants.h);

    const pugi::xml_node params = src.child(exec, "parameters");
    c.params = readParameters(ParameterTable(src, params, c.nfluid > 0));
    c.params.cfl_number = c.constants.cflnumber;
    readDomain(src, params, c);

    if (pugi::xml_node m = exec.child("motion")) c.motion = gencase::readMotion(src, m);
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
    c.particles = std::move(h5.particles);
    return c;
}

std::vector<std::string> describeCase(const SolverCase& c) {
    const gencase::CaseConstants& k = c.constants;
    std::vector<std::string> out;
    out.push_back("particles: " + std::to_string(c.particles.size()) + " (fixed " +
                  std::to_string(c.nfixed) + ", moving " + std::to_string(c.nmoving) + ", solid " +
                  std::to_string(c.nsolid) + ", fluid " + std::to_string(c.nfluid) + "), " +
                  std::to_string(k.dimensions) + "D");
    out.push_back("dp=" + num(k.dp) + " m, h=" + num(k.h) + " m, c0=" + num(k.speedsound) +
                  " m/s, B=" + num(k.b) + " Pa, rho0=" + num(k.rhop0) +
                  " kg/m^3, gamma=" + num(k.gamma));
    out.push_back("mass: fluid " + num(k.massfluid) + " kg, boundary " + num(k.massbound) + " kg");
    out.push_back("domain: " + vec(c.domain_min) + " - " + vec(c.domain_max) + " m");
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
