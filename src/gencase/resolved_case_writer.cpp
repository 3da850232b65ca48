// SeaSpring — MIT licence.
/// \file resolved_case_writer.cpp
#include "gencase/resolved_case_writer.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <filesystem>
#include <ostream>
#include <vector>

#include "core/error.h"
#include "core/version.h"
#include "io/case_h5.h"
#include "io/vtu_writer.h"

namespace seaspring::gencase {

namespace fs = std::filesystem;

namespace {

std::string fmt(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

void setXyz(pugi::xml_node n, Vec3d v) {
    n.append_attribute("x") = fmt(v.x).c_str();
    n.append_attribute("y") = fmt(v.y).c_str();
    n.append_attribute("z") = fmt(v.z).c_str();
}

void appendParticles(pugi::xml_node exec, const GeneratedCase& g) {
    pugi::xml_node parts = exec.append_child("particles");
    parts.append_attribute("np") = std::to_string(g.particles.size()).c_str();
    parts.append_attribute("nfixed") = std::to_string(g.count(ParticleType::Fixed)).c_str();
    parts.append_attribute("nmoving") = std::to_string(g.count(ParticleType::Moving)).c_str();
    parts.append_attribute("nsolid") = std::to_string(g.count(ParticleType::Solid)).c_str();
    parts.append_attribute("nfluid") = std::to_string(g.count(ParticleType::Fluid)).c_str();
    parts.append_attribute("mkboundfirst") = g.mkconfig.fluidcount + 1;
    parts.append_attribute("mkfluidfirst") = 1;
    for (const MkBlock& b : g.blocks) {
        pugi::xml_node n = parts.append_child(particleTypeName(b.type));
        n.append_attribute("mk") = b.mk;
        n.append_attribute(b.type == ParticleType::Fluid ? "mkfluid" : "mkbound") = b.mk_user;
        n.append_attribute("begin") = std::to_string(b.begin).c_str();
        n.append_attribute("count") = std::to_string(b.count).c_str();
    }
}

void appendSolids(pugi::xml_node exec, const GeneratedCase& g) {
    if (g.solids.empty()) return;
    pugi::xml_node v = exec.append_child("vcpmsolids");
    v.append_attribute("particles") = std::to_string(g.bond_stats.solid_particles).c_str();
    v.append_attribute("bonds") = std::to_string(g.bond_stats.bonds).c_str();
    v.append_attribute("clampbonds") = std::to_string(g.bond_stats.clamp_bonds).c_str();
    v.append_attribute("surface") = std::to_string(g.bond_stats.surface_particles).c_str();
    v.append_attribute("bondslots") = std::to_string(g.bonds.bondSlots()).c_str();
    for (const SolidSpec& s : g.solids) {
        pugi::xml_node n = v.append_child("solid");
        n.append_attribute("mkbound") = s.mkbound;
        n.append_attribute("mk") = s.mk;
        std::string clamps;
        for (int c : s.clamp_mkbound) clamps += (clamps.empty() ? "" : ",") + std::to_string(c);
        n.append_attribute("mkclamp") = clamps.c_str();
        n.append_attribute("density") = fmt(s.density).c_str();
        n.append_attribute("youngmod") = fmt(s.youngmod).c_str();
        n.append_attribute("poissratio") = fmt(s.poissratio).c_str();
        n.append_attribute("critstretch") = fmt(s.critstretch).c_str();
        n.append_attribute("damping") = fmt(s.damping).c_str();
        n.append_attribute("declaredin") = s.declared_in.c_str();
        for (const PointLoad& l : s.loads) {
            pugi::xml_node p = n.append_child("pointload");
            p.append_attribute("x") = fmt(l.x).c_str();
            p.append_attribute("y") = fmt(l.y).c_str();
            p.append_attribute("z") = fmt(l.z).c_str();
            p.append_attribute("fx") = fmt(l.fx).c_str();
            p.append_attribute("fy") = fmt(l.fy).c_str();
            p.append_attribute("fz") = fmt(l.fz).c_str();
            p.append_attribute("ratex") = fmt(l.ratex).c_str();
            p.append_attribute("ratey") = fmt(l.ratey).c_str();
            p.append_attribute("ratez") = fmt(l.ratez).c_str();
        }
        const auto it = g.bond_stats.particles_per_mk.find(s.mk);
        n.append_attribute("particles") =
            std::to_string(it == g.bond_stats.particles_per_mk.end() ? 0 : it->second).c_str();
    }
}

std::string today() {
    const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", std::gmtime(&t));
    return buf;
}

}  // namespace

void buildResolvedCase(pugi::xml_document& doc, const XmlSource& src, const GeneratedCase& g,
                       const std::string& particles_file) {
    pugi::xml_node decl = doc.prepend_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    decl.append_attribute("encoding") = "UTF-8";
    pugi::xml_node root = doc.append_child("case");
    root.append_attribute("app") = ("SeaSpring gencase " + std::string(kVersion)).c_str();
    root.append_attribute("date") = today().c_str();
    root.append_attribute("source") = fs::absolute(src.path()).string().c_str();
    root.append_copy(src.root().child("casedef"));
    pugi::xml_node exec = root.append_child("execution");
    pugi::xml_node in_exec = src.root().child("execution");
    if (pugi::xml_node sp = in_exec.child("special")) {
        // <gauges> as read (plain numbers, lengths resolved): the solver needs no expressions.
        pugi::xml_node copy = exec.append_copy(sp);
        while (pugi::xml_node gs = copy.child("gauges")) copy.remove_child(gs);
        for (pugi::xml_node c = copy.first_child(); c;) {  // disabled "_gauges" too
            pugi::xml_node next = c.next_sibling();
            if (std::string(c.name()) == "_gauges") copy.remove_child(c);
            c = next;
        }
        if (!g.gauges.empty()) writeGauges(g.gauges, copy);
    }
    pugi::xml_node params = exec.append_child("parameters");
    for (const auto& [key, value] : g.parameters) {
        pugi::xml_node p = params.append_child("parameter");
        p.append_attribute("key") = key.c_str();
        p.append_attribute("value") = value.c_str();
    }
    pugi::xml_node dom = params.append_child("simulationdomain");
    setXyz(dom.append_child("posmin"), g.domain.min);
    setXyz(dom.append_child("posmax"), g.domain.max);
    writeConstants(exec, g.constants);
    appendParticles(exec, g);
    if (!g.motion.empty()) writeMotion(g.motion, exec);
    appendSolids(exec, g);
    pugi::xml_node files = exec.append_child("files");
    files.append_attribute("particles") = particles_file.c_str();
}

void writeGeneratedCase(const XmlSource& src, const GeneratedCase& g, const std::string& output_base,
                        bool save_vtk, std::ostream& log) {
    const fs::path base(output_base);
    if (base.has_parent_path()) fs::create_directories(base.parent_path());
    const std::string name = base.filename().string();
    struct Output { std::string part, final_path; };
    std::vector<Output> outputs;
    auto cleanup = [&]() {
        std::error_code ec;
        for (const Output& o : outputs) fs::remove(o.part, ec);
    };
    try {
        const std::string h5 = output_base + ".h5";
        outputs.push_back({h5 + ".part", h5});
        io::CaseFileHeader header{g.name, g.constants.dimensions, g.constants.dp,
                                  static_cast<std::uint64_t>(g.particles.size()),
                                  "SeaSpring gencase " + std::string(kVersion)};
        io::writeCaseH5(outputs.back().part, header, g.particles, g.solids.empty() ? nullptr : &g.bonds);
        if (save_vtk) {
            const std::string vtu = output_base + ".vtu";
            outputs.push_back({vtu + ".part", vtu});
            std::vector<io::VtuExtraArray> extra;
            if (!g.solids.empty()) {
                std::vector<std::uint8_t> count(g.particles.size(), 0), clamp(g.particles.size(), 0);
                for (std::size_t r = 0; r < g.bonds.solidCount(); ++r) {
                    const std::size_t i = g.bonds.first_solid + r;
                    count[i] = std::uint8_t(g.bonds.offset[r + 1] - g.bonds.offset[r]);
                    for (std::uint32_t s = g.bonds.offset[r]; s < g.bonds.offset[r + 1]; ++s)
                        if (g.bonds.kind[s] & BondClampFlag) ++clamp[i];
                }
                extra.push_back({"bonds", std::move(count)});
                extra.push_back({"clampbonds", std::move(clamp)});
            }
            io::writeParticlesVtu(outputs.back().part, g.particles, extra);
        }
        const std::string xml = output_base + ".xml";
        outputs.push_back({xml + ".part", xml});
        pugi::xml_document doc;
        buildResolvedCase(doc, src, g, name + ".h5");
        if (!doc.save_file(outputs.back().part.c_str(), "  "))
            throw Error("cannot write " + outputs.back().part);
        // Only plain files (or nothing) may stand where the outputs go, so that the renames
        // below cannot fail half-way and leave a partial set.
        for (const Output& o : outputs)
            if (fs::exists(o.final_path) && !fs::is_regular_file(o.final_path))
                throw Error(o.final_path + ": exists and is not a regular file; remove it or choose another output name");
        std::vector<std::string> renamed;
        try {
            for (const Output& o : outputs) {
                fs::rename(o.part, o.final_path);
                renamed.push_back(o.final_path);
            }
        } catch (...) {
            std::error_code ec;
            for (const std::string& f : renamed) fs::remove(f, ec);
            throw;
        }
    } catch (...) {
        cleanup();
        throw;
    }
    for (const Output& o : outputs) log << "Written " << o.final_path << "\n";
}

}  // namespace seaspring::gencase
