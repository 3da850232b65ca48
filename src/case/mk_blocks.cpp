// SeaSpring — MIT licence.
/// \file mk_blocks.cpp
#include "case/mk_blocks.h"

#include <set>
#include <string>

namespace seaspring::model {

namespace {

ParticleType blockType(const XmlSource& src, pugi::xml_node n) {
    const std::string name = n.name();
    for (ParticleType t :
         {ParticleType::Fixed, ParticleType::Moving, ParticleType::Solid, ParticleType::Fluid})
        if (name == particleTypeName(t)) return t;
    src.fail(n, "is not a particle block (expected fixed, moving, solid or fluid)");
}

}  // namespace

void writeParticleBlocks(pugi::xml_node parent, const std::vector<MkBlock>& blocks, int mkboundfirst) {
    std::uint64_t np = 0, by_type[4] = {0, 0, 0, 0};
    for (const MkBlock& b : blocks) {
        np += b.count;
        by_type[int(b.type)] += b.count;
    }
    pugi::xml_node parts = parent.append_child("particles");
    parts.append_attribute("np") = std::to_string(np).c_str();
    parts.append_attribute("nfixed") = std::to_string(by_type[int(ParticleType::Fixed)]).c_str();
    parts.append_attribute("nmoving") = std::to_string(by_type[int(ParticleType::Moving)]).c_str();
    parts.append_attribute("nsolid") = std::to_string(by_type[int(ParticleType::Solid)]).c_str();
    parts.append_attribute("nfluid") = std::to_string(by_type[int(ParticleType::Fluid)]).c_str();
    parts.append_attribute("mkboundfirst") = mkboundfirst;
    parts.append_attribute("mkfluidfirst") = 1;
    for (const MkBlock& b : blocks) {
        pugi::xml_node n = parts.append_child(particleTypeName(b.type));
        n.append_attribute("mk") = b.mk;
        n.append_attribute(b.type == ParticleType::Fluid ? "mkfluid" : "mkbound") = b.mk_local;
        n.append_attribute("begin") = std::to_string(b.begin).c_str();
        n.append_attribute("count") = std::to_string(b.count).c_str();
    }
}

ParticleBlocks readParticleBlocks(const XmlSource& src, pugi::xml_node parts,
                                  std::vector<pugi::xml_node>* nodes) {
    ParticleBlocks c;
    src.checkAttributes(
        parts, {"np", "nfixed", "nmoving", "nsolid", "nfluid", "mkboundfirst", "mkfluidfirst"});
    c.np = src.count(parts, "np");
    c.nfixed = src.count(parts, "nfixed");
    c.nmoving = src.count(parts, "nmoving");
    c.nsolid = src.count(parts, "nsolid");
    c.nfluid = src.count(parts, "nfluid");
    const std::uint32_t np = c.np;
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
        b.mk = int(src.count(n, "mk", 65535));
        b.mk_local = int(src.count(n, local, 65535));
        b.begin = src.count(n, "begin");
        b.count = src.count(n, "count");
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
        if (nodes) nodes->push_back(n);
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
    return c;
}

}  // namespace seaspring::model
