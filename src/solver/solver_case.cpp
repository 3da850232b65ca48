// SeaSpring — MIT licence.
/// \file solver_case.cpp
/// \brief Reading and checking the resolved case for the solver.
#include "solver/solver_case.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
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

struct RawParameter {
    std::string value;
    pugi::xml_node node;
};

class ParameterReader {
public:
    ParameterReader(const XmlSource& src, pugi::xml_node params) : src_(src) {
        for (pugi::xml_node n : params.children("parameter")) {
            const std::string key = n.attribute("key").as_string();
            if (key.empty() || key[0] == '#') continue;
            if (!findParameter(key))
                src_.fail(n, "unknown parameter key \"" + key + "\" (the resolved case must come from gencase)");
            raw_[key] = {n.attribute("value").as_string(), n};
        }
    }
    /// The numeric value of `key`, its default when absent.
    double number(const std::string& key) const {
        const auto it = raw_.find(key);
        const ParameterInfo* info = findParameter(key);
        const std::string text = it != raw_.end() ? it->second.value
                                                  : std::string(info && info->default_value ? info->default_value : "");
        if (text.empty()) {
            if (it != raw_.end()) src_.fail(it->second.node, "parameter " + key + " has no value");
            throw Error(src_.path() + ": required parameter " + key + " is missing");
        }
        try {
            return gencase::parseNumber(text);
        } catch (const std::exception&) {
            if (it != raw_.end())
                src_.fail(it->second.node, "parameter " + key + "=\"" + text + "\" is not a number");
            throw Error(src_.path() + ": parameter " + key + "=\"" + text + "\" is not a number");
        }
    }
    int integer(const std::string& key, std::initializer_list<int> allowed, const std::string& meaning) const {
        const double v = number(key);
        for (int a : allowed)
            if (v == a) return a;
        fail(key, "=" + text(key) + " is not supported by seaspring (supported: " + meaning + ")");
    }
    std::string text(const std::string& key) const {
        const auto it = raw_.find(key);
        if (it != raw_.end()) return it->second.value;
        const ParameterInfo* info = findParameter(key);
        return info && info->default_value ? info->default_value : "";
    }
    /// Error unless the key keeps its "off" value.
    void requireOff(const std::string& key, const std::string& off, const std::string& what) const {
        const std::string t = text(key);
        bool is_off = t == off;
        if (!is_off) {
            try {
                is_off = gencase::parseNumber(t) == gencase::parseNumber(off);
            } catch (const std::exception&) {
            }
        }
        if (!is_off) fail(key, "=\"" + t + "\": " + what + " is not supported by seaspring");
    }
    [[noreturn]] void fail(const std::string& key, const std::string& msg) const {
        const auto it = raw_.find(key);
        if (it != raw_.end()) src_.fail(it->second.node, "parameter " + key + msg);
        throw Error(src_.path() + ": parameter " + key + msg);
    }
    void positive(const std::string& key, double v) const {
        if (!(v > 0)) fail(key, "=" + text(key) + " must be > 0");
    }
    void nonNegative(const std::string& key, double v) const {
        if (!(v >= 0)) fail(key, "=" + text(key) + " must be >= 0");
    }

private:
    const XmlSource& src_;
    std::map<std::string, RawParameter> raw_;
};

ParticleType blockType(const XmlSource& src, pugi::xml_node n) {
    const std::string name = n.name();
    if (name == "fixed") return ParticleType::Fixed;
    if (name == "moving") return ParticleType::Moving;
    if (name == "solid") return ParticleType::Solid;
    if (name == "fluid") return ParticleType::Fluid;
    src.fail(n, "unknown particle block (expected fixed, moving, solid or fluid)");
}

std::uint32_t uattr(const XmlSource& src, pugi::xml_node n, const char* a) {
    const pugi::xml_attribute at = n.attribute(a);
    if (!at) src.fail(n, std::string("attribute ") + a + " is missing");
    const double v = gencase::parseNumber(at.as_string());
    if (!(v >= 0) || v != std::floor(v) || v > 4294967295.0)
        src.fail(n, std::string("attribute ") + a + "=\"" + at.as_string() + "\" is not a count");
    return std::uint32_t(v);
}

}  // namespace

SolverCase loadSolverCase(const std::string& path) {
    SolverCase c;
    std::string xml = path;
    if (fs::path(xml).extension() != ".xml") xml += ".xml";
    if (!fs::exists(xml)) throw Error(xml + ": no such file (give OUTDIR/NAME as written by gencase)");
    c.xml_path = xml;
    XmlSource src(xml);
    const pugi::xml_node root = src.root();
    if (std::string(root.name()) != "case") src.fail(root, "the root element must be <case>");
    c.name = fs::path(xml).stem().string();
    const pugi::xml_node exec = src.child(root, "execution");
    const pugi::xml_node params = src.child(exec, "parameters");
    const pugi::xml_node constants = src.child(exec, "constants");
    c.constants = gencase::readConstants(src, constants);

    // Parameters.
    const ParameterReader pr(src, params);
    SolverParameters& p = c.params;
    p.step_algorithm = pr.integer("StepAlgorithm", {1, 2}, "1 Verlet, 2 symplectic");
    p.verlet_steps = int(pr.number("VerletSteps"));
    if (p.verlet_steps < 1) pr.fail("VerletSteps", "=" + pr.text("VerletSteps") + " must be >= 1");
    p.kernel = pr.integer("Kernel", {1, 2}, "1 cubic spline, 2 Wendland");
    p.visco_treatment = pr.integer("ViscoTreatment", {1, 2, 3}, "1 artificial, 2 laminar+SPS, 3 laminar");
    p.visco = pr.number("Visco");
    pr.nonNegative("Visco", p.visco);
    p.visco_bound_factor = pr.number("ViscoBoundFactor");
    pr.nonNegative("ViscoBoundFactor", p.visco_bound_factor);
    p.density_dt = pr.integer("DensityDT", {0, 1, 2, 3}, "0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full");
    p.density_dt_value = pr.number("DensityDTvalue");
    pr.nonNegative("DensityDTvalue", p.density_dt_value);
    p.coef_dt_min = pr.number("CoefDtMin");
    pr.positive("CoefDtMin", p.coef_dt_min);
    p.dt_ini = pr.number("DtIni");
    pr.nonNegative("DtIni", p.dt_ini);
    p.dt_min = pr.number("DtMin");
    pr.nonNegative("DtMin", p.dt_min);
    p.dt_fixed = pr.number("DtFixed");
    pr.nonNegative("DtFixed", p.dt_fixed);
    p.dt_all_particles = pr.integer("DtAllParticles", {0}, "0: dt from fluid particles") != 0;
    p.time_max = pr.number("TimeMax");
    pr.positive("TimeMax", p.time_max);
    p.time_out = pr.number("TimeOut");
    pr.positive("TimeOut", p.time_out);
    p.rhop_out_min = pr.number("RhopOutMin");
    p.rhop_out_max = pr.number("RhopOutMax");
    if (!(p.rhop_out_min < p.rhop_out_max))
        pr.fail("RhopOutMax", "=" + pr.text("RhopOutMax") + " must exceed RhopOutMin=" + pr.text("RhopOutMin"));
    p.min_fluid_stop = pr.number("MinFluidStop");
    pr.nonNegative("MinFluidStop", p.min_fluid_stop);
    p.wrn_parts_out = pr.number("WrnPartsOut");
    p.cfl_number = c.constants.cflnumber;
    pr.integer("Boundary", {1}, "1 DBC; mDBC is not implemented");
    pr.requireOff("Shifting", "0", "particle shifting");
    pr.requireOff("ViscoTime", "NONE", "a viscosity time table");
    pr.requireOff("DtFixedFile", "NONE", "a dt file");
    for (const char* k : {"XPeriodicIncY", "XPeriodicIncZ", "YPeriodicIncX", "YPeriodicIncZ", "ZPeriodicIncX",
                          "ZPeriodicIncY", "XYPeriodic", "XZPeriodic", "YZPeriodic"})
        pr.requireOff(k, "0", "periodic boundaries");
    pr.requireOff("Symmetry", "0", "a symmetry plane");
    if (!(c.constants.h > 0 && c.constants.speedsound > 0 && c.constants.b > 0 && c.constants.dp > 0))
        src.fail(constants, "h, speedsound, b and dp must be > 0");
    if (!(c.constants.cflnumber > 0 && c.constants.cflnumber <= 1))
        src.fail(constants, "cflnumber must be in (0, 1]");

    // Domain.
    const pugi::xml_node dom = src.child(params, "simulationdomain");
    const gencase::ExpressionEvaluator ev;
    c.domain_min = src.vec3(src.child(dom, "posmin"), ev);
    c.domain_max = src.vec3(src.child(dom, "posmax"), ev);
    if (!(c.domain_min.x <= c.domain_max.x && c.domain_min.y <= c.domain_max.y && c.domain_min.z <= c.domain_max.z))
        src.fail(dom, "posmin must not exceed posmax");

    // Particle blocks.
    const pugi::xml_node parts = src.child(exec, "particles");
    const std::uint32_t np = uattr(src, parts, "np");
    c.nfixed = uattr(src, parts, "nfixed");
    c.nmoving = uattr(src, parts, "nmoving");
    c.nsolid = uattr(src, parts, "nsolid");
    c.nfluid = uattr(src, parts, "nfluid");
    if (std::uint64_t(c.nfixed) + c.nmoving + c.nsolid + c.nfluid != np)
        src.fail(parts, "nfixed+nmoving+nsolid+nfluid differs from np=" + std::to_string(np));
    std::uint32_t next = 0;
    for (pugi::xml_node n : parts.children()) {
        if (n.type() != pugi::node_element) continue;
        MkBlock b;
        b.type = blockType(src, n);
        b.mk = int(uattr(src, n, "mk"));
        b.mk_local = int(uattr(src, n, b.type == ParticleType::Fluid ? "mkfluid" : "mkbound"));
        b.begin = uattr(src, n, "begin");
        b.count = uattr(src, n, "count");
        if (b.begin != next) src.fail(n, "block begins at " + std::to_string(b.begin) + ", expected " + std::to_string(next));
        next = b.begin + b.count;
        c.blocks.push_back(b);
    }
    if (next != np) src.fail(parts, "the blocks hold " + std::to_string(next) + " particles, np is " + std::to_string(np));

    // Motion.
    if (pugi::xml_node m = exec.child("motion")) c.motion = gencase::readMotion(src, m);

    // Particles.
    const pugi::xml_node files = src.child(exec, "files");
    c.h5_path = (fs::path(src.directory()) / src.text(files, "particles")).string();
    if (!fs::exists(c.h5_path)) src.fail(files, "particle file " + c.h5_path + " does not exist");
    io::CaseFileContents h5 = io::readCaseH5(c.h5_path);
    if (h5.particles.size() != np)
        throw Error(c.h5_path + ": holds " + std::to_string(h5.particles.size()) + " particles but " + src.where(parts) +
                    " says np=" + std::to_string(np));
    if (h5.header.dimensions != c.constants.dimensions)
        throw Error(c.h5_path + ": dimensions " + std::to_string(h5.header.dimensions) + " differ from the case's " +
                    std::to_string(c.constants.dimensions));
    for (const MkBlock& b : c.blocks)
        for (std::uint32_t i = b.begin; i < b.begin + b.count; ++i)
            if (h5.particles.type[i] != b.type || h5.particles.mk[i] != b.mk)
                throw Error(c.h5_path + ": particle " + std::to_string(i) + " (type " +
                            particleTypeName(h5.particles.type[i]) + ", mk " + std::to_string(h5.particles.mk[i]) +
                            ") does not match its block at " + src.where(parts) + " (type " +
                            particleTypeName(b.type) + ", mk " + std::to_string(b.mk) + ")");
    c.particles = std::move(h5.particles);
    if (h5.has_bonds) c.bonds = std::move(h5.bonds);
    return c;
}

std::vector<std::string> describeCase(const SolverCase& c) {
    std::vector<std::string> out;
    char line[320];
    std::snprintf(line, sizeof line, "particles: %zu (fixed %u, moving %u, solid %u, fluid %u), %dD",
                  c.particles.size(), c.nfixed, c.nmoving, c.nsolid, c.nfluid, c.constants.dimensions);
    out.push_back(line);
    std::snprintf(line, sizeof line, "dp=%g m  h=%.6g m  c0=%.6g m/s  B=%.6g Pa  rho0=%g  mass fluid=%.6g bound=%.6g kg",
                  c.constants.dp, c.constants.h, c.constants.speedsound, c.constants.b, c.constants.rhop0,
                  c.constants.massfluid, c.constants.massbound);
    out.push_back(line);
    std::snprintf(line, sizeof line, "domain: (%g, %g, %g) - (%g, %g, %g) m", c.domain_min.x, c.domain_min.y,
                  c.domain_min.z, c.domain_max.x, c.domain_max.y, c.domain_max.z);
    out.push_back(line);
    if (!c.motion.empty()) out.push_back("motion objects: " + std::to_string(c.motion.objects.size()));
    return out;
}

}  // namespace seaspring::solver
