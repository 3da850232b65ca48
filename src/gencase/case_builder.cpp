// SeaSpring — MIT licence.
/// \file case_builder.cpp
#include "gencase/case_builder.h"
#include "core/format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>

#include "core/case_parameters.h"
#include "case/case_checks.h"
#include "core/error.h"
#include "gencase/resolved_case_writer.h"

namespace seaspring::gencase {

namespace fs = std::filesystem;

std::size_t GeneratedCase::count(ParticleType t) const {
    std::size_t n = 0;
    for (const MkBlock& b : blocks)
        if (b.type == t) n += b.count;
    return n;
}

std::string resolveDefinitionPath(const std::string& path) {
    if (fs::exists(path) && fs::is_regular_file(path)) return path;
    if (fs::exists(path + ".xml")) return path + ".xml";
    throwInputError(path, 0, "case definition not found (also tried " + path + ".xml)");
}

void checkOutputBase(const std::string& definition, const std::string& output_base) {
    const fs::path base(output_base);
    const std::string name = base.filename().string();
    if (name.empty() || name == "." || name == "..")
        throwInputError(output_base.empty() ? "\"\"" : output_base, 0,
                        "the output must be OUTDIR/NAME, ending in a file name (NAME.xml and NAME.h5 are written)");
    std::error_code ec;
    const fs::path def = fs::weakly_canonical(definition, ec);
    for (const char* ext : {".xml", ".h5", ".vtu"}) {
        const fs::path out = fs::weakly_canonical(output_base + ext, ec);
        if (!ec && out == def)
            throwInputError(output_base, 0, "the output " + output_base + ext + " is the case definition " + definition +
                                                " itself: choose another OUTDIR/NAME (gencase never overwrites its input)");
    }
}

CaseBuilder::CaseBuilder(GencaseOptions options, std::ostream& log)
    : opt_(std::move(options)), log_(log) {}

CaseBuilder::~CaseBuilder() = default;

const GeneratedCase& CaseBuilder::build() {
    if (opt_.dp_override < 0 || std::isnan(opt_.dp_override))
        throwInputError("-dp", 0, "dp=" + std::to_string(opt_.dp_override) + ": must be > 0");
    const std::string definition = resolveDefinitionPath(opt_.definition);
    checkOutputBase(definition, opt_.output_base);
    src_ = std::make_unique<XmlSource>(definition);
    out_.name = fs::path(opt_.output_base).filename().string();
    pugi::xml_node root = src_->root();
    if (std::string(root.name()) != "case") src_->fail(root, "root element must be <case>");
    src_->checkAttributes(root, {"app", "date"});
    src_->checkChildren(root, {"casedef", "execution"});
    src_->checkUnique(root, {"casedef", "execution"});
    pugi::xml_node casedef = src_->child(root, "casedef");
    readHeader(casedef);
    drawGeometry(src_->child(casedef, "geometry"));
    if (pugi::xml_node m = casedef.child("motion")) out_.motion = parseMotion(*src_, m, ev_);
    readExecution(root.child("execution"));
    finishParticles();
    computeNormals(casedef.child("normals"));
    readGauges(root.child("execution"));
    resolveParameters(root.child("execution").child("parameters"));
    printSummary();
    return out_;
}

void CaseBuilder::readHeader(pugi::xml_node casedef) {
    src_->checkAttributes(casedef, {"requiredversion"});
    for (pugi::xml_node n : casedef.children()) {
        if (XmlSource::isDisabled(n)) continue;
        const std::string name = n.name();
        if (name == "floatings" || name == "initials" || name == "properties" || name == "patterns" ||
            name == "vres")
            src_->fail(n, "is not supported by SeaSpring yet (see docs/case-format.md)");
    }
    src_->checkChildren(casedef, {"constantsdef", "mkconfig", "geometry", "motion", "normals"});
    src_->checkUnique(casedef, {"constantsdef", "mkconfig", "geometry", "motion", "normals"});
    if (pugi::xml_node mk = casedef.child("mkconfig")) {
        src_->checkAttributes(mk, {"boundcount", "fluidcount"});
        src_->checkChildren(mk, {});
        out_.mkconfig.boundcount = src_->integer(mk, "boundcount", ev_, 240);
        out_.mkconfig.fluidcount = src_->integer(mk, "fluidcount", ev_, 9);
        if (out_.mkconfig.fluidcount < 1 || out_.mkconfig.boundcount < 1 ||
            out_.mkconfig.fluidcount + out_.mkconfig.boundcount > 65535)
            src_->fail(mk, "fluidcount and boundcount must be >= 1 and sum to at most 65535");
    }
    pugi::xml_node geometry = src_->child(casedef, "geometry");
    // Variables of <predefinition> may be used by <constantsdef> and <definition>.
    src_->checkChildren(geometry, {"predefinition", "definition", "commands"});
    src_->checkUnique(geometry, {"predefinition", "definition", "commands"});
    CommandRunner vars(*src_, ev_, grid_, out_.mkconfig, log_, false);
    if (pugi::xml_node pre = geometry.child("predefinition")) {
        src_->checkChildren(pre, {"newvar", "newvarcte"});
        for (pugi::xml_node v : pre.children())
            if (!XmlSource::isDisabled(v)) vars.defineVariables(v, std::string(v.name()) == "newvarcte", false);
    }
    if (pugi::xml_node cd = casedef.child("constantsdef"))
        constants_in_ = parseConstantsDef(*src_, cd, ev_);
}

void CaseBuilder::drawGeometry(pugi::xml_node geometry) {
    pugi::xml_node def = src_->child(geometry, "definition");
    src_->checkAttributes(def, {"dp"});
    src_->checkChildren(def, {"pointref", "pointmin", "pointmax"});
    src_->checkUnique(def, {"pointref", "pointmin", "pointmax"});
    double dp = src_->number(def, "dp", ev_);
    if (opt_.dp_override > 0) dp = opt_.dp_override;
    if (!(dp > 0)) src_->fail(def, "dp=\"" + std::string(def.attribute("dp").value()) + "\": must be > 0");
    ev_.define("Dp", dp, true);
    Vec3d ref{0, 0, 0};
    if (pugi::xml_node r = def.child("pointref")) {
        src_->checkAttributes(r, {"x", "y", "z"});
        ref = src_->vec3(r, ev_);
    }
    pugi::xml_node nmin = src_->child(def, "pointmin"), nmax = src_->child(def, "pointmax");
    src_->checkAttributes(nmin, {"x", "y", "z"});
    src_->checkAttributes(nmax, {"x", "y", "z"});
    const Vec3d pmin = src_->vec3(nmin, ev_), pmax = src_->vec3(nmax, ev_);
    if (pmin.x > pmax.x || pmin.y > pmax.y || pmin.z > pmax.z)
        src_->fail(def, "pointmin must not exceed pointmax in any axis");
    try {
        grid_ = LatticeGrid(ref, dp, pmin, pmax);
    } catch (const Error& e) {
        src_->fail(def, e.what());
    }
    ev_.setGrid(grid_.origin(), dp);
    log_ << "Lattice: dp=" << dp << (grid_.twoD() ? " (2D)" : " (3D)") << ", " << grid_.nx() << " x "
         << grid_.ny() << " x " << grid_.nz() << " sites\n";
    CommandRunner runner(*src_, ev_, grid_, out_.mkconfig, log_, opt_.verbose);
    runner.run(src_->child(geometry, "commands"));
    out_.shapes = runner.shapeSets();
}

void CaseBuilder::computeNormals(pugi::xml_node normals) {
    const NormalsRequest req = readNormals(*src_, normals, ev_, out_.shapes, out_.name);
    if (!req.active) return;
    ParticleSet& p = out_.particles;
    const CaseConstants& c = out_.constants;
    p.normal = computeGhostVectors(p.pos, p.boundaryCount(), req.shapes->faces, req.distanceh * c.h, c.dp,
                                   grid_.twoD(), src_->path(), &out_.normals_stats);
    out_.normals_set = req.shapes->name;
    printNormalsSummary(log_, out_.normals_set, out_.normals_stats, c.dp);
}

void CaseBuilder::readExecution(pugi::xml_node execution) {
    pugi::xml_node special, parameters;
    if (execution) {
        src_->checkChildren(execution, {"special", "parameters"});
        src_->checkUnique(execution, {"special", "parameters"});
        special = execution.child("special");
        parameters = execution.child("parameters");
    }
    if (special) {
        src_->checkUnique(special, {"vcpmsolids", "flexstrucs", "gauges", "savedt"});
        for (pugi::xml_node n : special.children()) {
            if (XmlSource::isDisabled(n)) continue;
            const std::string name = n.name();
            if (name != "vcpmsolids" && name != "flexstrucs" && name != "gauges" && name != "savedt")
                src_->fail(n, "is not supported by SeaSpring (supported in <special>: vcpmsolids, "
                              "flexstrucs, gauges, savedt)");
        }
        out_.solids = parseSolids(*src_, special, ev_, out_.mkconfig, grid_.twoD() ? 2 : 3, log_);
    }
}

void CaseBuilder::readGauges(pugi::xml_node execution) {
    const pugi::xml_node node = execution.child("special").child("gauges");
    if (!node || XmlSource::isDisabled(node)) return;
    out_.gauges = parseGauges(*src_, node, ev_, out_.constants.dp, out_.constants.h);
    for (const GaugeSpec& g : out_.gauges.gauges) {
        if (g.kind != GaugeKind::Force && g.kind != GaugeKind::SolidMarker) continue;
        const bool marker = g.kind == GaugeKind::SolidMarker;
        if (marker && out_.solids.empty())
            throwInputError(src_->path(), g.line, "<solidmarker name=\"" + g.name +
                                                      "\">: the case has no VCPM solid (<vcpmsolids>)");
        if (g.target_mkbound < 0) continue;
        bool found = false;
        for (const MkBlock& b : out_.blocks)
            if (b.type != ParticleType::Fluid && b.mk_local == g.target_mkbound &&
                (!marker || b.type == ParticleType::Solid))
                found = true;
        if (!found)
            throwInputError(src_->path(), g.line, "<" + std::string(gaugeElementName(g.kind)) + " name=\"" + g.name +
                                                      "\">: target mkbound=" + std::to_string(g.target_mkbound) +
                                                      (marker ? " is not a VCPM solid with particles"
                                                              : " has no boundary particles"));
    }
    log_ << "Gauges: " << out_.gauges.gauges.size() << "\n";
}

void CaseBuilder::resolveParameters(pugi::xml_node parameters) {
    std::map<std::string, std::string> given;
    std::map<std::string, pugi::xml_node> nodes;  // the <parameter> of each key given
    if (parameters) {
        src_->checkChildren(parameters, {"parameter", "simulationdomain"});
        src_->checkUnique(parameters, {"simulationdomain"});
        for (pugi::xml_node p : parameters.children("parameter")) {
            src_->checkAttributes(p, {"key", "value"});
            const std::string key = src_->text(p, "key");
            if (!key.empty() && key[0] == '#') continue;  // commented out, as in the shared cases
            const ParameterInfo* info = findParameter(key);
            if (!info) src_->fail(p, "key=\"" + key + "\" is not a known parameter (see docs/case-format.md)");
            if (given.count(key)) src_->fail(p, "key=\"" + key + "\" is given twice");
            std::string value = src_->text(p, "value");
            if (info->kind == ParameterKind::Number) {
                const double v = src_->number(p, "value", ev_);  // validates; '#' expressions
                if (!value.empty() && value[0] == '#') value = exactText(v);  // written evaluated
            }
            if (info->kind == ParameterKind::Deprecated)
                log_ << "Note: " << src_->where(p) << ": parameter " << key << " is deprecated and ignored\n";
            else
                nodes[key] = p;
            given[key] = value;
        }
    }
    for (const ParameterInfo& info : knownParameters()) {
        if (info.kind == ParameterKind::Deprecated) continue;
        const bool needed = !info.default_value && (std::string(info.key) != "Visco" ||
                                                    out_.count(ParticleType::Fluid) > 0);
        if (needed && !given.count(info.key))
            src_->fail(parameters ? parameters : src_->root(),
                       std::string("misses the required parameter ") + info.key + " (" + info.meaning + ")");
        const auto it = given.find(info.key);
        if (it != given.end()) out_.parameters.emplace_back(info.key, it->second);
        else if (info.default_value) out_.parameters.emplace_back(info.key, info.default_value);
    }
    // What seaspring would reject, gencase rejects: the solver's own reader on these values.
    model::checkSolverParameters(*src_, parameters ? parameters : src_->root(), std::move(nodes), out_.parameters);
}

MkTypes CaseBuilder::classifyMks() const {
    MkTypes types;
    types.fill(ParticleType::Fixed);
    const MkConfig& mk = out_.mkconfig;
    for (int f = 0; f < mk.fluidcount; ++f) types[mk.fluidMk(f)] = ParticleType::Fluid;
    for (const MotionObject& o : out_.motion.objects) {
        if (o.mkbound < 0 || o.mkbound >= mk.boundcount)
            throwInputError(src_->path(), o.line, "motion ref=" + std::to_string(o.mkbound) +
                                                      ": expected a mkbound 0.." + std::to_string(mk.boundcount - 1));
        types[mk.boundMk(o.mkbound)] = ParticleType::Moving;
    }
    for (const SolidBody& s : out_.solids) {
        if (const MotionObject* o = out_.motion.find(s.mkbound))
            for (const Movement& m : o->movements)
                if (m.kind != MovementKind::Null)
                    throwInputError(src_->path(), s.line,
                                    "solid mkbound=" + std::to_string(s.mkbound) + " has a prescribed motion (line " +
                                        std::to_string(o->line) + "): a VCPM solid moves through its clamps; only mvnull is allowed");
        types[s.mk] = ParticleType::Solid;
    }
    return types;
}

void CaseBuilder::checkMkUsage() const {
    auto present = [&](std::uint16_t mk) {
        for (const MkBlock& b : out_.blocks)
            if (b.mk == mk) return true;
        return false;
    };
    for (const MotionObject& o : out_.motion.objects)
        if (!present(out_.mkconfig.boundMk(o.mkbound)))
            throwInputError(src_->path(), o.line, "motion ref=" + std::to_string(o.mkbound) +
                                                      ": no particle was drawn with setmkbound mk=\"" +
                                                      std::to_string(o.mkbound) + "\"");
    for (const SolidBody& s : out_.solids) {
        if (!present(s.mk))
            throwInputError(src_->path(), s.line, "solid mkbound=" + std::to_string(s.mkbound) +
                                                      " has no particles: draw it with setmkbound mk=\"" +
                                                      std::to_string(s.mkbound) + "\" on the lattice");
        for (std::size_t c = 0; c < s.clamp_mk.size(); ++c)
            if (!present(s.clamp_mk[c]))
                throwInputError(src_->path(), s.line, "mkclamp " + std::to_string(s.clamp_mkbound[c]) +
                                                          " does not exist: no particle was drawn with that mkbound");
    }
}

void CaseBuilder::finishParticles() {
    const MkTypes types = classifyMks();
    try {
        out_.particles = extractParticles(grid_, types, &lattice_);
    } catch (const Error& e) {
        src_->fail(src_->root().child("casedef").child("geometry").child("definition"), e.what());
    }
    ParticleSet& p = out_.particles;
    if (p.size() == 0) src_->fail(src_->root(), "the case has no particles: nothing was drawn inside pointmin..pointmax");
    if (p.size() > 0xFFFFFFF0ull) src_->fail(src_->root(), "more than 4e9 particles");
    // MK blocks.
    for (std::size_t i = 0; i < p.size();) {
        std::size_t j = i;
        while (j < p.size() && p.mk[j] == p.mk[i]) ++j;
        const int user = out_.mkconfig.isFluid(p.mk[i]) ? p.mk[i] - 1 : p.mk[i] - out_.mkconfig.fluidcount - 1;
        out_.blocks.push_back({p.type[i], p.mk[i], user, std::uint32_t(i), std::uint32_t(j - i)});
        i = j;
    }
    checkMkUsage();
    // Bounding boxes and automatic hswl.
    DomainBox box{p.pos[0], p.pos[0]};
    double zf_min = 1e300, zf_max = -1e300;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3d x = p.pos[i];
        box.min = {std::min(box.min.x, x.x), std::min(box.min.y, x.y), std::min(box.min.z, x.z)};
        box.max = {std::max(box.max.x, x.x), std::max(box.max.y, x.y), std::max(box.max.z, x.z)};
        if (p.type[i] == ParticleType::Fluid) {
            zf_min = std::min(zf_min, x.z);
            zf_max = std::max(zf_max, x.z);
        }
    }
    out_.particle_box = box;
    const double fluid_height = zf_max >= zf_min ? zf_max - zf_min : 0.0;
    out_.constants = computeConstants(constants_in_, grid_.dp(), grid_.twoD(), fluid_height);
    const CaseConstants& c = out_.constants;
    setInitialDensity(p, grid_, lattice_, c.rhopgradient, c.rhop0, c.b, c.gamma, c.gravity.z,
                      std::uint16_t(out_.mkconfig.fluidcount));
    const double volume = grid_.twoD() ? c.dp * c.dp : c.dp * c.dp * c.dp;
    std::map<std::uint16_t, float> solid_mass;
    for (const SolidBody& s : out_.solids) solid_mass[s.mk] = float(s.density * volume);
    for (std::size_t i = 0; i < p.size(); ++i) {
        switch (p.type[i]) {
            case ParticleType::Fluid: p.mass[i] = float(c.massfluid); break;
            case ParticleType::Solid: p.mass[i] = solid_mass[p.mk[i]]; break;
            default: p.mass[i] = float(c.massbound);
        }
    }
    if (!out_.solids.empty()) {
        BondBuildInput in{grid_.twoD(), grid_.dp(), &lattice_, &p, {}};
        for (const SolidBody& s : out_.solids) in.clamp_mks[s.mk] = s.clamp_mk;
        try {
            out_.bonds = buildBondNetwork(in, &out_.bond_stats);
        } catch (const Error& e) {
            src_->fail(src_->root().child("execution").child("special"), e.what());
        }
        for (SolidBody& s : out_.solids) {
            const auto it = out_.bond_stats.particles_per_mk.find(s.mk);
            s.particles = it == out_.bond_stats.particles_per_mk.end() ? 0 : it->second;
        }
    }
    pugi::xml_node sd = src_->root().child("execution").child("parameters").child("simulationdomain");
    out_.domain = resolveSimulationDomain(*src_, sd, ev_, box);
}

void CaseBuilder::checkForSolver() const {
    const pugi::xml_node casedef = src_->root().child("casedef");
    model::checkCaseHasWork(*src_, src_->root(), out_.count(ParticleType::Fluid), out_.count(ParticleType::Solid));
    const std::size_t nfixed_moving = out_.count(ParticleType::Fixed) + out_.count(ParticleType::Moving);
    model::checkCaseConstants(*src_, casedef.child("constantsdef"), casedef, out_.constants,
                              out_.count(ParticleType::Fluid) > 0, nfixed_moving > 0);
}

void CaseBuilder::write() const {
    writeGeneratedCase(*src_, out_, opt_.output_base, opt_.save_vtk, log_);
}

void CaseBuilder::printSummary() const {
    const GeneratedCase& g = out_;
    printConstants(log_, g.constants);
    log_ << "Particles: " << g.particles.size() << " (fixed " << g.count(ParticleType::Fixed) << ", moving "
         << g.count(ParticleType::Moving) << ", solid " << g.count(ParticleType::Solid) << ", fluid "
         << g.count(ParticleType::Fluid) << ")\n";
    for (const MkBlock& b : g.blocks)
        log_ << "  MK " << b.mk << " (" << (b.type == ParticleType::Fluid ? "mkfluid " : "mkbound ")
             << b.mk_local << ", " << particleTypeName(b.type) << "): " << b.count << " particles, ids "
             << b.begin << ".." << (b.begin + b.count - 1) << "\n";
    if (!g.solids.empty())
        log_ << "VCPM solids: " << g.bond_stats.solid_particles << " particles, " << g.bond_stats.bonds
             << " bonds, " << g.bond_stats.clamp_bonds << " clamp bonds, " << g.bond_stats.surface_particles
             << " particles with an incomplete neighbourhood (surface)\n";
    log_ << "Domain: (" << g.domain.min.x << ", " << g.domain.min.y << ", " << g.domain.min.z << ") - ("
         << g.domain.max.x << ", " << g.domain.max.y << ", " << g.domain.max.z << ")\n";
}

}  // namespace seaspring::gencase
