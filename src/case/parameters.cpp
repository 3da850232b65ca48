// SeaSpring — MIT licence.
/// \file parameters.cpp
#include "case/parameters.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>

#include "core/case_parameters.h"
#include "core/format.h"

namespace seaspring::model {

namespace {

void setXyz(pugi::xml_node n, Vec3d v) {
    n.append_attribute("x") = exactText(v.x).c_str();
    n.append_attribute("y") = exactText(v.y).c_str();
    n.append_attribute("z") = exactText(v.z).c_str();
}

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

    /// gencase: the entries it read and resolved itself (`nodes`: the <parameter> of each key
    /// given; `values`: every key's value, expressions evaluated and defaults filled in).
    ParameterTable(const XmlSource& src, pugi::xml_node params, std::map<std::string, pugi::xml_node> nodes,
                   const ParameterValues& values)
        : src_(src), params_(params), given_(std::move(nodes)), values_(values.begin(), values.end()) {}

    /// The value as written, or the default ("" for an absent required key).
    std::string text(const std::string& key) const {
        if (const auto v = values_.find(key); v != values_.end()) return v->second;
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
            return parseNumber(t);
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
                 feature + " is not supported by seaspring (supported: " + shortText(off) + ", off)");
    }
    void requireNone(const std::string& key, const std::string& feature) const {
        const std::string t = text(key);
        if (t != "NONE" && !t.empty())
            fail(key, feature + " is not supported by seaspring (supported: NONE)");
    }
    double atLeast(const std::string& key, double lo, bool inclusive) const {
        const double v = number(key);
        if (inclusive ? !(v >= lo) : !(v > lo))
            fail(key, std::string("must be ") + (inclusive ? ">= " : "> ") + shortText(lo));
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
    std::map<std::string, std::string> values_;  ///< gencase's resolved values (empty in the solver)
};

SolverParameters readParameters(const ParameterTable& t) {
    SolverParameters p;
    t.number("SavePosDouble");  // positions are always double in seaspring
    p.boundary = t.choice("Boundary", {1, 2}, "1 DBC, 2 mDBC");
    if (p.boundary == 2) {
        p.slip_mode = t.choice("SlipMode", {1, 2, 3}, "1 DBC vel=0, 2 no-slip, 3 free-slip");
        p.mdbc_threshold = t.atLeast("MDbcThreshold", 0, true);
        if (p.mdbc_threshold > 1) t.fail("MDbcThreshold", "is a kernel sum: must be <= 1");
        t.requireOff("NoPenetration", 0, "mDBC's no-penetration correction");
    } else {  // mDBC only: checked to be numbers, as DualSPHysics ignores them with DBC
        t.number("SlipMode");
        t.number("MDbcThreshold");
        t.number("NoPenetration");
    }
    p.step_algorithm = t.choice("StepAlgorithm", {1, 2}, "1 Verlet, 2 symplectic");
    p.verlet_steps = t.integer("VerletSteps");
    if (p.verlet_steps < 1) t.fail("VerletSteps", "must be >= 1");
    p.kernel = t.choice("Kernel", {1, 2}, "1 cubic spline, 2 Wendland");
    p.visco_treatment =
        t.choice("ViscoTreatment", {1, 2, 3}, "1 artificial, 2 laminar+SPS, 3 laminar");
    p.visco = t.atLeast("Visco", 0, true);
    p.laminar_lattice_correction = t.choice("LaminarLatticeCorrection", {0, 1}, "0 DualSPHysics' laminar operator, 1 its lattice bias divided out");
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
    p.vcpm_contact = t.choice("VcpmContact", {0, 1}, "0 none, 1 contact of VCPM solids");
    p.vcpm_contact_stiffness = t.atLeast("VcpmContactStiffness", 0, false);
    if (p.vcpm_contact_stiffness > 2)
        t.fail("VcpmContactStiffness", "must be <= 2 (a multiple of the bond stiffness; the sub-step limit grows with it)");
    p.vcpm_contact_damping = t.atLeast("VcpmContactDamping", 0, true);
    if (p.vcpm_contact_damping > 1) t.fail("VcpmContactDamping", "is a fraction of critical damping: must be <= 1");
    p.vcpm_contact_friction = t.atLeast("VcpmContactFriction", 0, true);
    p.vcpm_surface_correction = t.choice("VcpmSurfaceCorrection", {0, 1}, "0 none (the plain lattice), 1 surface correction (springs, volumetric weights, clamp bonds)");
    p.vcpm_row_bending = t.choice("VcpmRowBending", {-1, 0, 1},
                                  "-1 auto (1 with VcpmSurfaceCorrection 1, else 0), 0 none, 1 the rows' own bending "
                                  "(with VcpmSurfaceCorrection 1)");
    if (p.vcpm_row_bending == 1 && p.vcpm_surface_correction == 0)
        t.fail("VcpmRowBending", "needs VcpmSurfaceCorrection 1 (the rows' bending is part of the surface correction)");
    // The rows' bending completes the surface correction (docs/vcpm.md, "The rows' own bending"):
    // on with it by default.
    if (p.vcpm_row_bending < 0) p.vcpm_row_bending = p.vcpm_surface_correction;
    p.vcpm_substep_bound = t.choice("VcpmSubStepBound", {-1, 0, 1},
                                    "-1 auto (1 with VcpmRowBending 1, else 0), 0 Gershgorin's bounds, 1 the bodies' "
                                    "largest stiffness eigenvalues");
    // The rows' bending stiffens the short waves of thin bodies beyond what Gershgorin's ratio
    // allows for (docs/vcpm.md, "The rows' own bending"): with it, the exact factor by default.
    if (p.vcpm_substep_bound < 0) p.vcpm_substep_bound = p.vcpm_row_bending == 1 ? 1 : 0;
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

}  // namespace

void writeParameters(pugi::xml_node parent, const ParameterValues& values, const DomainBox& domain) {
    pugi::xml_node params = parent.append_child("parameters");
    for (const auto& [key, value] : values) {
        pugi::xml_node p = params.append_child("parameter");
        p.append_attribute("key") = key.c_str();
        p.append_attribute("value") = value.c_str();
    }
    pugi::xml_node dom = params.append_child("simulationdomain");
    setXyz(dom.append_child("posmin"), domain.min);
    setXyz(dom.append_child("posmax"), domain.max);
}

SolverParameters readSolverParameters(const XmlSource& src, pugi::xml_node parameters, bool has_fluid) {
    return readParameters(ParameterTable(src, parameters, has_fluid));
}

SolverParameters checkSolverParameters(const XmlSource& src, pugi::xml_node parameters,
                                       std::map<std::string, pugi::xml_node> nodes, const ParameterValues& values) {
    return readParameters(ParameterTable(src, parameters, std::move(nodes), values));
}

DomainBox readSimulationDomain(const XmlSource& src, pugi::xml_node params, int dimensions) {
    src.checkUnique(params, {"simulationdomain"});
    const pugi::xml_node dom = src.child(params, "simulationdomain");
    src.checkChildren(dom, {"posmin", "posmax"});
    const PlainNumbers ev;
    DomainBox box;
    box.min = src.vec3(src.child(dom, "posmin"), ev);
    box.max = src.vec3(src.child(dom, "posmax"), ev);
    const double lo[3] = {box.min.x, box.min.y, box.min.z};
    const double hi[3] = {box.max.x, box.max.y, box.max.z};
    for (int k = 0; k < 3; ++k) {
        const bool flat_ok = k == 1 && dimensions == 2;
        if (flat_ok ? !(lo[k] <= hi[k]) : !(lo[k] < hi[k]))
            src.fail(dom, "posmin " + shortVec(box.min) + " must lie below posmax " + shortVec(box.max) + " in " +
                              "xyz"[k]);
    }
    return box;
}

}  // namespace seaspring::model
