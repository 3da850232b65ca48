// SeaSpring — MIT licence.
/// \file vcpm_solids.cpp
#include "gencase/vcpm_solids.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <ostream>
#include <sstream>

#include "core/error.h"

namespace seaspring::gencase {

namespace {

int toInt(const XmlSource& src, pugi::xml_node node, const char* attr, const std::string& s) {
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || v < 0)
        src.fail(node, std::string(attr) + "=\"" + node.attribute(attr).value() +
                           "\": expected MK numbers like \"1\" or \"0,2-3\"");
    return int(v);
}

std::string trimAll(std::string s) {
    s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
    return s;
}

void validate(const XmlSource& src, pugi::xml_node n, SolidBody& s, const MkConfig& mk, int dim) {
    auto bad = [&](const std::string& what) { src.fail(n, what); };
    const std::string model = model::constitModelProblem(s.constitmodel, dim);
    if (!model.empty()) bad(model);
    if (s.mkbound < 0 || s.mkbound >= mk.boundcount)
        bad("mkbound=" + std::to_string(s.mkbound) + ": expected 0.." + std::to_string(mk.boundcount - 1));
    if (!(s.density > 0)) bad("density=" + std::to_string(s.density) + ": must be > 0 [kg/m^3]");
    if (!(s.youngmod > 0)) bad("youngmod=" + std::to_string(s.youngmod) + ": must be > 0 [Pa]");
    if (!(s.poissratio > -1.0 && s.poissratio < 0.5))
        bad("poissratio=" + std::to_string(s.poissratio) + ": must lie in (-1, 0.5)");
    if (!(s.critstretch >= 0)) bad("critstretch=" + std::to_string(s.critstretch) + ": must be >= 0");
    if (!(s.damping >= 0)) bad("damping=" + std::to_string(s.damping) + ": must be >= 0");
    s.mk = mk.boundMk(s.mkbound);
    for (int c : s.clamp_mkbound) {
        if (c == s.mkbound) bad("mkclamp names the solid's own mkbound " + std::to_string(c));
        if (c >= mk.boundcount)
            bad("mkclamp " + std::to_string(c) + ": expected 0.." + std::to_string(mk.boundcount - 1));
        s.clamp_mk.push_back(mk.boundMk(c));
    }
}

}  // namespace

std::vector<int> parseMkList(const XmlSource& src, pugi::xml_node node, const char* attr) {
    std::vector<int> out;
    const std::string text = trimAll(src.text(node, attr));
    if (text.empty() || text.front() == ',' || text.back() == ',' || text.find(",,") != std::string::npos)
        src.fail(node, std::string(attr) + "=\"" + node.attribute(attr).value() +
                           "\": expected MK numbers like \"1\" or \"0,2-3\" (an item is empty)");
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const auto dash = item.find('-');
        if (dash == std::string::npos) {
            out.push_back(toInt(src, node, attr, item));
        } else {
            const int a = toInt(src, node, attr, item.substr(0, dash));
            const int b = toInt(src, node, attr, item.substr(dash + 1));
            if (b < a) src.fail(node, std::string(attr) + ": range " + item + " is reversed");
            for (int v = a; v <= b; ++v) out.push_back(v);
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<SolidBody> parseSolids(const XmlSource& src, pugi::xml_node special,
                                   const ExpressionEvaluator& ev, const MkConfig& mk, int dim,
                                   std::ostream& log) {
    std::vector<SolidBody> solids;
    if (pugi::xml_node v = special.child("vcpmsolids")) {
        src.checkChildren(v, {"solid"});
        src.checkAttributes(v, {});
        for (pugi::xml_node n : v.children("solid")) {
            src.checkAttributes(n, {"mkbound", "mkclamp", "density", "youngmod", "poissratio", "constitmodel",
                                    "critstretch", "tensilestrength", "damping"});
            SolidBody s;
            s.line = src.lineOf(n);
            s.declared_in = "vcpmsolids";
            s.mkbound = src.integer(n, "mkbound", ev);
            if (n.attribute("mkclamp")) s.clamp_mkbound = parseMkList(src, n, "mkclamp");
            s.density = src.number(n, "density", ev);
            s.youngmod = src.number(n, "youngmod", ev);
            s.poissratio = src.number(n, "poissratio", ev);
            if (n.attribute("constitmodel")) s.constitmodel = src.integer(n, "constitmodel", ev);
            s.critstretch = src.number(n, "critstretch", ev, 0.0);
            if (n.attribute("tensilestrength")) {
                // Seed 000, Eq. A1 (after Chen & Liu 2016): critical elongation
                // alpha = 1.25 sigma_T (1 + nu) / (2E) of the bond's rest length.
                if (n.attribute("critstretch"))
                    src.fail(n, "give either critstretch or tensilestrength, not both");
                const double sigma = src.number(n, "tensilestrength", ev);
                if (!(sigma > 0))
                    src.fail(n, "tensilestrength=\"" + std::string(n.attribute("tensilestrength").value()) +
                                    "\": must be > 0 [Pa]");
                s.critstretch = 1.25 * sigma * (1.0 + s.poissratio) / (2.0 * s.youngmod);
                log << "Note: " << src.where(n) << ": tensilestrength " << sigma
                    << " Pa gives critstretch 1.25 sigma_T (1+nu)/(2E) = " << s.critstretch << "\n";
            }
            s.damping = src.number(n, "damping", ev, 0.0);
            src.checkChildren(n, {"pointload"});
            for (pugi::xml_node l : n.children("pointload")) {
                src.checkAttributes(l, {"x", "y", "z", "fx", "fy", "fz", "ratex", "ratey", "ratez"});
                PointLoad p;
                p.line = src.lineOf(l);
                p.point.x = src.number(l, "x", ev);
                p.point.y = src.number(l, "y", ev);
                p.point.z = src.number(l, "z", ev);
                p.force.x = src.number(l, "fx", ev, 0.0);
                p.force.y = src.number(l, "fy", ev, 0.0);
                p.force.z = src.number(l, "fz", ev, 0.0);
                p.rate.x = src.number(l, "ratex", ev, 0.0);
                p.rate.y = src.number(l, "ratey", ev, 0.0);
                p.rate.z = src.number(l, "ratez", ev, 0.0);
                s.loads.push_back(p);
            }
            validate(src, n, s, mk, dim);
            solids.push_back(s);
        }
    }
    if (pugi::xml_node f = special.child("flexstrucs")) {
        src.checkChildren(f, {"flexstrucbody"});
        src.checkAttributes(f, {});
        for (pugi::xml_node n : f.children("flexstrucbody")) {
            src.checkAttributes(n, {"mkbound", "mkclamp"});
            src.checkChildren(n, {"density", "youngmod", "poissratio", "constitmodel", "hgfactor"});
            SolidBody s;
            s.line = src.lineOf(n);
            s.declared_in = "flexstrucs";
            s.mkbound = src.integer(n, "mkbound", ev);
            if (n.attribute("mkclamp")) s.clamp_mkbound = parseMkList(src, n, "mkclamp");
            for (pugi::xml_node c : n.children())
                if (!XmlSource::isDisabled(c)) src.checkAttributes(c, {"value"});
            s.density = src.number(src.child(n, "density"), "value", ev);
            s.youngmod = src.number(src.child(n, "youngmod"), "value", ev);
            s.poissratio = src.number(src.child(n, "poissratio"), "value", ev);
            if (pugi::xml_node cm = n.child("constitmodel"); cm && !XmlSource::isDisabled(cm))
                s.constitmodel = src.integer(cm, "value", ev);
            validate(src, n, s, mk, dim);
            log << "Note: " << src.where(n) << ": <flexstrucbody mkbound=\"" << s.mkbound
                << "\"> is modelled as a VCPM lattice solid (constitmodel " << model::effectiveConstitModel(s, dim)
                << " is kept: 1 plane strain, 2 plane stress, 3 3D; hgfactor does not apply)\n";
            solids.push_back(s);
        }
    }
    for (std::size_t i = 0; i < solids.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (solids[i].mkbound == solids[j].mkbound)
                throwInputError(src.path(), solids[i].line,
                                "solid mkbound=" + std::to_string(solids[i].mkbound) +
                                    " is declared twice (first at line " + std::to_string(solids[j].line) + ")");
    for (const SolidBody& s : solids)
        for (const SolidBody& o : solids)
            if (std::find(s.clamp_mkbound.begin(), s.clamp_mkbound.end(), o.mkbound) != s.clamp_mkbound.end())
                throwInputError(src.path(), s.line,
                                "mkclamp " + std::to_string(o.mkbound) +
                                    " is itself a solid: a solid can only be clamped to fixed or moving boundaries");
    return solids;
}

}  // namespace seaspring::gencase
