// SeaSpring — MIT licence.
/// \file solid_body.cpp
#include "case/solid_body.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include "core/format.h"

namespace seaspring::model {

namespace {

/// A plain-number attribute of a resolved element.
double plainNumber(const XmlSource& src, pugi::xml_node n, const char* attr) {
    try {
        return parseNumber(src.text(n, attr));
    } catch (const std::exception& e) {
        src.fail(n, std::string(attr) + "=\"" + n.attribute(attr).value() + "\": " + e.what());
    }
}

PointLoad readLoad(const XmlSource& src, pugi::xml_node l) {
    src.checkAttributes(l, {"x", "y", "z", "fx", "fy", "fz", "ratex", "ratey", "ratez"});
    auto lnum = [&](const char* attr) { return plainNumber(src, l, attr); };
    PointLoad load;
    load.line = src.lineOf(l);
    load.point = Vec3d{lnum("x"), lnum("y"), lnum("z")};
    load.force = Vec3d{lnum("fx"), lnum("fy"), lnum("fz")};
    load.rate = Vec3d{lnum("ratex"), lnum("ratey"), lnum("ratez")};
    return load;
}

/// `mkclamp="1,3"`: the mkbound numbers and the global MKs of their fixed or moving blocks.
void readClamps(const XmlSource& src, pugi::xml_node s, const std::vector<MkBlock>& blocks, SolidBody& b) {
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
        for (const MkBlock& blk : blocks)
            if ((blk.type == ParticleType::Fixed || blk.type == ParticleType::Moving) && blk.mk_local == mkb) {
                b.clamp_mk.push_back(std::uint16_t(blk.mk));
                found = true;
            }
        if (!found)
            src.fail(s, "mkclamp=\"" + clamps + "\": mkbound " + item + " has no fixed or moving particle block");
        b.clamp_mkbound.push_back(int(mkb));
        if (comma == std::string::npos) break;
        from = comma + 1;
    }
}

SolidBody readSolid(const XmlSource& src, pugi::xml_node s, const std::vector<MkBlock>& blocks) {
    src.checkAttributes(s, {"mkbound", "mk", "mkclamp", "density", "youngmod", "poissratio", "constitmodel",
                            "critstretch", "damping", "declaredin", "particles"});
    SolidBody b;
    b.line = src.lineOf(s);
    auto number = [&](const char* attr) { return plainNumber(src, s, attr); };
    b.mkbound = int(src.count(s, "mkbound", 65535));
    b.mk = std::uint16_t(src.count(s, "mk", 65535));
    b.density = number("density");
    b.youngmod = number("youngmod");
    b.poissratio = number("poissratio");
    if (s.attribute("constitmodel")) b.constitmodel = int(src.count(s, "constitmodel", 3));
    b.critstretch = number("critstretch");
    b.damping = number("damping");
    if (!(b.density > 0)) src.fail(s, "density=\"" + shortText(b.density) + "\": must be > 0 [kg/m^3]");
    if (!(b.youngmod > 0)) src.fail(s, "youngmod=\"" + shortText(b.youngmod) + "\": must be > 0 [Pa]");
    if (!(b.poissratio > -1 && b.poissratio < 0.5))
        src.fail(s, "poissratio=\"" + shortText(b.poissratio) + "\": must lie in (-1, 0.5)");
    if (!(b.critstretch >= 0)) src.fail(s, "critstretch=\"" + shortText(b.critstretch) + "\": must be >= 0");
    if (!(b.damping >= 0)) src.fail(s, "damping=\"" + shortText(b.damping) + "\": must be >= 0");
    src.checkChildren(s, {"pointload"});
    for (pugi::xml_node l : s.children("pointload")) b.loads.push_back(readLoad(src, l));
    readClamps(src, s, blocks, b);
    b.declared_in = src.text(s, "declaredin", "");
    if (s.attribute("particles")) b.particles = src.count(s, "particles");
    return b;
}

}  // namespace

void writeSolids(pugi::xml_node parent, const std::vector<SolidBody>& solids, const SolidTotals& totals) {
    pugi::xml_node v = parent.append_child("vcpmsolids");
    v.append_attribute("particles") = std::to_string(totals.particles).c_str();
    v.append_attribute("bonds") = std::to_string(totals.bonds).c_str();
    v.append_attribute("clampbonds") = std::to_string(totals.clampbonds).c_str();
    v.append_attribute("surface") = std::to_string(totals.surface).c_str();
    v.append_attribute("bondslots") = std::to_string(totals.bondslots).c_str();
    for (const SolidBody& s : solids) {
        pugi::xml_node n = v.append_child("solid");
        n.append_attribute("mkbound") = s.mkbound;
        n.append_attribute("mk") = s.mk;
        std::string clamps;
        for (int c : s.clamp_mkbound) clamps += (clamps.empty() ? "" : ",") + std::to_string(c);
        n.append_attribute("mkclamp") = clamps.c_str();
        n.append_attribute("density") = exactText(s.density).c_str();
        n.append_attribute("youngmod") = exactText(s.youngmod).c_str();
        n.append_attribute("poissratio") = exactText(s.poissratio).c_str();
        if (s.constitmodel != 0) n.append_attribute("constitmodel") = s.constitmodel;
        n.append_attribute("critstretch") = exactText(s.critstretch).c_str();
        n.append_attribute("damping") = exactText(s.damping).c_str();
        n.append_attribute("declaredin") = s.declared_in.c_str();
        for (const PointLoad& l : s.loads) {
            pugi::xml_node p = n.append_child("pointload");
            p.append_attribute("x") = exactText(l.point.x).c_str();
            p.append_attribute("y") = exactText(l.point.y).c_str();
            p.append_attribute("z") = exactText(l.point.z).c_str();
            p.append_attribute("fx") = exactText(l.force.x).c_str();
            p.append_attribute("fy") = exactText(l.force.y).c_str();
            p.append_attribute("fz") = exactText(l.force.z).c_str();
            p.append_attribute("ratex") = exactText(l.rate.x).c_str();
            p.append_attribute("ratey") = exactText(l.rate.y).c_str();
            p.append_attribute("ratez") = exactText(l.rate.z).c_str();
        }
        n.append_attribute("particles") = std::to_string(s.particles).c_str();
    }
}

std::vector<SolidBody> readSolids(const XmlSource& src, pugi::xml_node vcpmsolids,
                                  const std::vector<MkBlock>& blocks, SolidTotals& totals) {
    src.checkChildren(vcpmsolids, {"solid"});
    totals.particles = src.count(vcpmsolids, "particles");
    totals.bondslots = src.count(vcpmsolids, "bondslots");
    std::vector<SolidBody> solids;
    for (pugi::xml_node s : vcpmsolids.children("solid")) solids.push_back(readSolid(src, s, blocks));
    return solids;
}

int effectiveConstitModel(const SolidBody& s, int dim) {
    return s.constitmodel != 0 ? s.constitmodel : (dim == 2 ? 1 : 3);
}

std::string constitModelProblem(int constitmodel, int dim) {
    if (constitmodel < 0 || constitmodel > 3)
        return "constitmodel=" + std::to_string(constitmodel) +
               ": expected 1 (plane strain, 2D), 2 (plane stress, 2D) or 3 (3D)";
    if (dim == 2 && constitmodel == 3)
        return "constitmodel=3 (St Venant-Kirchhoff, 3D) in a 2D case: use 1 (plane strain) or 2 (plane stress)";
    if (dim == 3 && (constitmodel == 1 || constitmodel == 2))
        return "constitmodel=" + std::to_string(constitmodel) + " (plane " +
               (constitmodel == 1 ? "strain" : "stress") + ", 2D) in a 3D case: use 3";
    return "";
}

}  // namespace seaspring::model
