// SeaSpring — MIT licence.
/// \file resolved_case_writer.cpp
#include "gencase/resolved_case_writer.h"

#include <chrono>
#include <ctime>
#include <string>
#include <filesystem>
#include <ostream>
#include <vector>

#include "case/case_constants.h"
#include "case/gauge_spec.h"
#include "case/mk_blocks.h"
#include "case/motion_xml.h"
#include "case/parameters.h"
#include "case/solid_body.h"
#include "core/error.h"
#include "core/version.h"
#include "io/case_h5.h"
#include "io/vtu_writer.h"

namespace seaspring::gencase {

namespace fs = std::filesystem;

namespace {

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
        if (!g.gauges.empty()) model::writeGauges(g.gauges, copy);
    }
    model::writeParameters(exec, g.parameters, g.domain);
    model::writeConstants(exec, g.constants);
    model::writeParticleBlocks(exec, g.blocks, g.mkconfig.fluidcount + 1);
    if (!g.motion.empty()) model::writeMotion(g.motion, exec);
    if (!g.solids.empty()) {
        const model::SolidTotals totals{g.bond_stats.solid_particles, g.bond_stats.bonds, g.bond_stats.clamp_bonds,
                                        g.bond_stats.surface_particles, g.bonds.bondSlots()};
        model::writeSolids(exec, g.solids, totals);
    }
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
        // Shape sets as GenCase names them ([CaseName]_X_Actual.vtk), for ParaView.
        for (const ShapeSet& set : g.shapes) {
            if (set.faces.empty()) continue;
            const fs::path dir = base.has_parent_path() ? base.parent_path() : fs::path();
            const fs::path vtk = dir / shapeFileName(name, set.name);
            outputs.push_back({vtk.string() + ".part", vtk.string()});
            writeShapeVtk(outputs.back().part, set);
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
