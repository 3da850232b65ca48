// SeaSpring — MIT licence.
/// \file command_runner.cpp
#include "gencase/command_runner.h"

#include <algorithm>
#include <cctype>
#include <ostream>
#include <sstream>

#include "core/error.h"

namespace seaspring::gencase {

using model::parseNumber;

namespace {

constexpr int kMaxListDepth = 32;
/// The most commands one case may run, runlist repetitions counted (GenCase cases run a few
/// thousand): lists that call lists many times over stop with an error instead of running for
/// ever.
constexpr std::uint64_t kMaxCommandsRun = 1000000;

std::string trimmed(const std::string& s) {
    std::size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : s) {
        if (c == sep) { out.push_back(trimmed(cur)); cur.clear(); }
        else cur += c;
    }
    out.push_back(trimmed(cur));
    return out;
}

unsigned faceBits(const std::string& word, bool& ok) {
    if (word == "solid") return BoxSolid;
    if (word == "all") return FacesAll;
    if (word == "left") return FaceLeft;
    if (word == "right") return FaceRight;
    if (word == "front") return FaceFront;
    if (word == "back") return FaceBack;
    if (word == "bottom") return FaceBottom;
    if (word == "top") return FaceTop;
    ok = false;
    return 0;
}

DrawMode parseDrawMode(const XmlSource& src, pugi::xml_node cmd) {
    const std::string m = src.text(cmd, "mode");
    if (m == "full") return DrawMode::Full;
    if (m == "face") return DrawMode::Face;
    if (m == "solid") return DrawMode::Solid;
    src.fail(cmd, "mode=\"" + m + "\": expected full, face or solid (wire is not supported)");
}

}  // namespace

unsigned parseBoxFill(const std::string& text, bool& ok) {
    ok = true;
    unsigned mask = 0;
    for (const std::string& term : split(text, '|')) {
        const std::vector<std::string> parts = split(term, '^');
        unsigned t = faceBits(parts[0], ok);
        for (std::size_t i = 1; i < parts.size(); ++i) t &= ~faceBits(parts[i], ok);
        mask |= t;
    }
    if ((mask & BoxSolid) && (mask & FacesAll)) ok = false;  // "solid" cannot be mixed with faces
    return ok ? mask : 0;
}

CommandRunner::CommandRunner(const XmlSource& src, ExpressionEvaluator& ev, LatticeGrid& grid,
                             MkConfig mk, std::ostream& log, bool verbose)
    : src_(src), ev_(ev), grid_(grid), mkcfg_(mk), log_(log), verbose_(verbose) {}

void CommandRunner::run(pugi::xml_node commands) {
    commands_ = commands;
    src_.checkChildren(commands, {"list", "mainlist"});
    for (pugi::xml_node l : commands.children("list")) src_.checkAttributes(l, {"name", "printcall"});
    pugi::xml_node main = src_.child(commands, "mainlist");
    runList(main, 0);
    if (!pending_faces_.empty())
        log_ << "Note: " << src_.path() << ":" << pending_first_line_ << ": " << pending_faces_.size()
             << " shape faces recorded from this line on are in no shape set (no <shapeout> follows them)\n";
}

void CommandRunner::runList(pugi::xml_node list, int depth) {
    if (depth > kMaxListDepth) src_.fail(list, "runlist nesting deeper than 32 (recursive lists?)");
    for (pugi::xml_node cmd : list.children()) {
        if (XmlSource::isDisabled(cmd)) continue;
        if (++commands_run_ > kMaxCommandsRun)
            src_.fail(cmd, "more than " + std::to_string(kMaxCommandsRun) +
                               " commands run: the runlist repetitions (times) of nested lists multiply");
        runCommand(cmd, depth);
    }
}

void CommandRunner::defineVariables(pugi::xml_node node, bool constant, bool assign) {
    for (pugi::xml_attribute a : node.attributes()) {
        const std::string name = a.name();
        if (name.empty() || name[0] == '_' || name == "comment" || name == "units_comment") continue;
        std::string expr = trimmed(a.value());
        if (!expr.empty() && expr[0] == '#') expr.erase(0, 1);
        double v = 0;
        try {
            v = ev_.evaluate(expr);
            if (assign) ev_.assign(name, v);
            else ev_.define(name, v, constant);
        } catch (const ExpressionError& e) {
            src_.fail(node, "variable " + name + "=\"" + a.value() + "\": " + e.what());
        }
    }
}

void CommandRunner::report(pugi::xml_node cmd, std::size_t count) {
    if (verbose_)
        log_ << "  " << src_.where(cmd) << " <" << cmd.name() << "> " << count << " points, mk "
             << mk_ << "\n";
}

std::vector<double> CommandRunner::layers(pugi::xml_node cmd, std::vector<bool>* marked) const {
    pugi::xml_node l = cmd.child("layers");
    if (marked) marked->clear();
    if (!l) {
        if (marked) marked->push_back(false);
        return {0.0};
    }
    src_.checkAttributes(l, {"vdp"});
    std::vector<double> out;
    for (std::string item : split(src_.text(l, "vdp"), ',')) {
        const bool star = !item.empty() && item.back() == '*';  // GenCase shape-output marker
        if (star) item.pop_back();
        if (marked) marked->push_back(star);
        try {
            out.push_back(parseNumber(item));
        } catch (const ExpressionError& e) {
            src_.fail(l, "vdp=\"" + std::string(l.attribute("vdp").value()) + "\": " + e.what());
        }
    }
    return out;
}

void CommandRunner::boxExtent(pugi::xml_node cmd, Vec3d& p0, Vec3d& size) const {
    p0 = src_.vec3(src_.child(cmd, "point"), ev_);
    const pugi::xml_node s = cmd.child("size"), e = cmd.child("endpoint");
    if (s && e) src_.fail(cmd, "gives both <size> and <endpoint>: use one");
    if (!s && !e) src_.fail(cmd, "requires <size> or <endpoint>");
    if (s) {
        src_.checkAttributes(s, {"x", "y", "z"});
        size = src_.vec3(s, ev_);
    } else {
        src_.checkAttributes(e, {"x", "y", "z"});
        size = src_.vec3(e, ev_) - p0;
    }
    src_.checkAttributes(src_.child(cmd, "point"), {"x", "y", "z"});
}

void CommandRunner::drawBoxCommand(pugi::xml_node cmd) {
    src_.checkAttributes(cmd, {});
    src_.checkChildren(cmd, {"boxfill", "point", "size", "endpoint", "layers"});
    bool ok = true;
    const std::string fill = cmd.child("boxfill") ? cmd.child("boxfill").text().get() : "solid";
    const unsigned faces = parseBoxFill(fill, ok);
    if (!ok || faces == 0)
        src_.fail(cmd.child("boxfill"), "\"" + fill +
                  "\": expected solid, or faces all|top|bottom|left|right|front|back joined by '|' "
                  "with '^' for exceptions");
    Vec3d p0, size;
    boxExtent(cmd, p0, size);
    const Vec3d p1 = p0 + size;
    const Vec3d lo0{std::min(p0.x, p1.x), std::min(p0.y, p1.y), std::min(p0.z, p1.z)};
    const Vec3d hi0{std::max(p0.x, p1.x), std::max(p0.y, p1.y), std::max(p0.z, p1.z)};
    const bool shapes = recordsShapes(cmd);
    std::vector<bool> marked;
    const std::vector<double> offsets = layers(cmd, &marked);
    // With a '*' on some layers only those are shapes (GenCase's "0*,1,2"), else all are.
    const bool any_marked = std::find(marked.begin(), marked.end(), true) != marked.end();
    std::size_t n = 0, nfaces = 0;
    for (std::size_t k = 0; k < offsets.size(); ++k) {
        const double v = offsets[k];
        // Layer v moves each drawn face outwards by v*dp (inwards when negative); the sides
        // that are not drawn stay put, so the layers of adjacent faces close the corners and
        // an open side stays flush (GenCase: SPHERIC tank counts match exactly).
        const double d = v * grid_.dp();
        Vec3d lo = lo0, hi = hi0;
        if (faces & BoxSolid) {
            lo = lo - Vec3d{d, d, d};
            hi = hi + Vec3d{d, d, d};
        } else {
            if (faces & FaceLeft) lo.x -= d;
            if (faces & FaceRight) hi.x += d;
            if (faces & FaceFront) lo.y -= d;
            if (faces & FaceBack) hi.y += d;
            if (faces & FaceBottom) lo.z -= d;
            if (faces & FaceTop) hi.z += d;
        }
        if (draw_points_) n += drawBox(grid_, matrix_, lo, hi - lo, faces, mk_);
        if (shapes && (!any_marked || marked[k])) nfaces += recordBoxShape(cmd, lo, hi, faces, v);
    }
    report(cmd, n);
    if (shapes && verbose_)
        log_ << "  " << src_.where(cmd) << " <drawbox> " << nfaces << " shape faces"
             << (normal_invert_ ? " (normals inverted)" : "") << "\n";
}

std::size_t CommandRunner::recordBoxShape(pugi::xml_node cmd, Vec3d lo, Vec3d hi, unsigned faces, double vdp) {
    const char* axis = hi.x < lo.x ? "x" : hi.z < lo.z ? "z" : (!grid_.twoD() && hi.y < lo.y) ? "y" : nullptr;
    if (axis)
        src_.fail(cmd.child("layers") ? cmd.child("layers") : cmd,
                  "the layer vdp=" + std::to_string(vdp) + " turns the box's shape inside out along " + axis);
    if (grid_.twoD() && hi.y < lo.y) std::swap(lo.y, hi.y);  // y plays no part in 2D
    const std::vector<ShapeFace> f = boxShapeFaces(matrix_, lo, hi, faces, normal_invert_, src_.lineOf(cmd));
    if (pending_faces_.empty()) pending_first_line_ = src_.lineOf(cmd);
    pending_faces_.insert(pending_faces_.end(), f.begin(), f.end());
    return f.size();
}

bool CommandRunner::recordsShapes(pugi::xml_node cmd) const {
    if (!draw_shapes_) return false;
    const unsigned kind = mk_ == 0 ? 4u : mkcfg_.isFluid(mk_) ? 2u : 1u;
    if ((shape_kinds_ & kind) == 0) return false;
    if (!shape_actual_)
        src_.fail(cmd, "draws shapes (<setactive drawshapes=\"1\"/>) but <setshapemode> selects dp shapes only; "
                       "SeaSpring records the actual geometry: add 'actual'");
    return true;
}

void CommandRunner::setShapeMode(pugi::xml_node cmd) {
    src_.checkAttributes(cmd, {});
    bool actual = false, dp = false;
    unsigned kinds = 0;
    bool any_kind = false;
    for (const std::string& w : split(cmd.text().get(), '|')) {
        if (w == "actual") actual = true;
        else if (w == "dp") dp = true;
        else if (w == "bound") kinds |= 1u;
        else if (w == "fluid") kinds |= 2u;
        else if (w == "void") kinds |= 4u;
        else if (w == "all") kinds |= 7u;
        else if (w != "null")
            src_.fail(cmd, "\"" + w + "\": expected actual, dp, all, bound, fluid, void or null");
        any_kind = any_kind || (w != "actual" && w != "dp");
    }
    shape_actual_ = actual || !dp;  // no geometry word: actual
    shape_kinds_ = any_kind ? kinds : 7u;
}

void CommandRunner::shapeOut(pugi::xml_node cmd) {
    src_.checkAttributes(cmd, {"file", "format", "reset", "savenormal"});
    const std::string name = src_.text(cmd, "file", "");
    if (name.find_first_of("/\\") != std::string::npos)
        src_.fail(cmd, "file=\"" + name + "\": a shape set name must not contain '/' or '\\'");
    const std::string format = src_.text(cmd, "format", "vtk");
    if (format != "vtk" && format != "VTK")
        src_.fail(cmd, "format=\"" + format + "\": SeaSpring writes shape files as VTK only");
    src_.boolean(cmd, "savenormal", true);  // the normals are always written
    const bool reset = src_.boolean(cmd, "reset", true);
    ShapeSet set{name, src_.lineOf(cmd), pending_faces_};
    if (reset) pending_faces_.clear();
    if (verbose_)
        log_ << "  " << src_.where(cmd) << " <shapeout> shape set '" << name << "': " << set.faces.size()
             << " faces" << (set.faces.empty() ? " (shapes are recorded only while <setactive drawshapes=\"1\"/>)" : "")
             << "\n";
    for (ShapeSet& s : shape_sets_)
        if (s.name == name) {
            if (!s.faces.empty())
                log_ << "Note: " << src_.where(cmd) << ": <shapeout> replaces shape set '" << name
                     << "' written at line " << s.line << "\n";
            s = std::move(set);
            return;
        }
    shape_sets_.push_back(std::move(set));
}

void CommandRunner::drawRoundCommand(pugi::xml_node cmd, bool cylinder) {
    src_.checkAttributes(cmd, {"radius"});
    src_.checkChildren(cmd, {"point", "layers"});
    const double radius = src_.number(cmd, "radius", ev_);
    if (!(radius > 0)) src_.fail(cmd, "radius=" + std::to_string(radius) + ": must be > 0");
    std::vector<Vec3d> pts;
    for (pugi::xml_node p : cmd.children("point")) {
        src_.checkAttributes(p, {"x", "y", "z"});
        pts.push_back(src_.vec3(p, ev_));
    }
    const std::size_t need = cylinder ? 2 : 1;
    if (pts.size() != need)
        src_.fail(cmd, "needs exactly " + std::to_string(need) + " <point> element(s), found " +
                           std::to_string(pts.size()));
    if (cylinder && dot(pts[1] - pts[0], pts[1] - pts[0]) == 0)
        src_.fail(cmd, "the two axis points are equal");
    if (recordsShapes(cmd))
        src_.fail(cmd, "normals geometry supports drawbox only: <" + std::string(cmd.name()) +
                           "> cannot be drawn while shapes are recorded (<setactive drawshapes=\"1\"/>); "
                           "switch drawshapes off around it");
    std::size_t n = 0;
    for (double v : layers(cmd)) {
        const double r = radius + v * grid_.dp();
        if (!(r > 0)) src_.fail(cmd.child("layers"), "a layer gives a radius <= 0");
        if (!draw_points_) continue;
        n += cylinder ? drawCylinder(grid_, matrix_, pts[0], pts[1], r, mode_, mk_)
                      : drawSphere(grid_, matrix_, pts[0], r, mode_, mk_);
    }
    report(cmd, n);
}

void CommandRunner::fillBoxCommand(pugi::xml_node cmd) {
    src_.checkAttributes(cmd, {"x", "y", "z"});
    src_.checkChildren(cmd, {"modefill", "point", "size", "endpoint"});
    const Vec3d seed = src_.vec3(cmd, ev_);
    unsigned mask = 0;
    const std::string modes = cmd.child("modefill") ? cmd.child("modefill").text().get() : "void";
    for (const std::string& w : split(modes, '|')) {
        if (w == "void") mask |= FillVoid;
        else if (w == "fluid") mask |= FillFluid;
        else if (w == "bound") mask |= FillBound;
        else if (w == "border") mask |= FillBorder;
        else
            src_.fail(cmd.child("modefill"), "\"" + w + "\": expected void, fluid, bound or border joined by '|'");
    }
    if (matrix_.hasRotation()) src_.fail(cmd, "is not supported after <rotate> (use matrixreset)");
    Vec3d p0, size;
    boxExtent(cmd, p0, size);
    if (!draw_points_) return;
    const std::size_t n = fillBox(grid_, matrix_, seed, p0, size, mask, mk_,
                                  std::uint16_t(mkcfg_.fluidcount));
    if (n == 0)
        log_ << "Warning: " << src_.where(cmd)
             << ": fillbox filled no point (the seed point is outside the box or on a site that "
                "<modefill> does not allow)\n";
    report(cmd, n);
}

void CommandRunner::runCommand(pugi::xml_node cmd, int depth) {
    const std::string name = cmd.name();
    if (name == "setmkfluid" || name == "setmkbound") {
        src_.checkAttributes(cmd, {"mk"});
        const int mk = src_.integer(cmd, "mk", ev_);
        const bool fluid = name == "setmkfluid";
        const int limit = fluid ? mkcfg_.fluidcount : mkcfg_.boundcount;
        if (mk < 0 || mk >= limit)
            src_.fail(cmd, "mk=" + std::to_string(mk) + ": expected 0.." + std::to_string(limit - 1) +
                               " (<mkconfig " + (fluid ? "fluidcount" : "boundcount") + "=\"" +
                               std::to_string(limit) + "\">)");
        mk_ = fluid ? mkcfg_.fluidMk(mk) : mkcfg_.boundMk(mk);
        mk_chosen_ = true;
    } else if (name == "setmkvoid") {
        src_.checkAttributes(cmd, {});
        mk_ = 0;
        mk_chosen_ = true;
    } else if (name == "setdrawmode") {
        src_.checkAttributes(cmd, {"mode"});
        mode_ = parseDrawMode(src_, cmd);
    } else if (name == "setshapemode") {
        setShapeMode(cmd);
    } else if (name == "setactive") {
        src_.checkAttributes(cmd, {"drawpoints", "drawshapes", "vtkout"});
        draw_points_ = src_.boolean(cmd, "drawpoints", draw_points_);
        draw_shapes_ = src_.boolean(cmd, "drawshapes", draw_shapes_);
    } else if (name == "setnormalinvert") {
        src_.checkAttributes(cmd, {"invert"});
        if (!cmd.attribute("invert")) src_.fail(cmd, "needs invert=\"true\" or invert=\"false\"");
        normal_invert_ = src_.boolean(cmd, "invert", false);
    } else if (name == "resetdraw") {
        src_.checkAttributes(cmd, {});
        mode_ = DrawMode::Full;
        matrix_ = Affine{};
        draw_points_ = true;
        draw_shapes_ = false;
    } else if (name == "shapeout") {
        shapeOut(cmd);
    } else if (name == "move") {
        src_.checkAttributes(cmd, {"x", "y", "z"});
        matrix_ = matrix_.then(Affine::translation(src_.vec3(cmd, ev_)));
    } else if (name == "rotate") {
        src_.checkAttributes(cmd, {"ang", "x", "y", "z"});
        const Vec3d axis = src_.vec3(cmd, ev_);
        if (dot(axis, axis) == 0) src_.fail(cmd, "rotation axis (x, y, z) is zero");
        matrix_ = matrix_.then(Affine::rotation(src_.number(cmd, "ang", ev_), axis));
    } else if (name == "matrixreset") {
        src_.checkAttributes(cmd, {});
        matrix_ = Affine{};
    } else if (name == "matrixsave") {
        src_.checkAttributes(cmd, {});
        saved_matrices_.push_back(matrix_);
    } else if (name == "matrixload") {
        src_.checkAttributes(cmd, {});
        if (saved_matrices_.empty()) src_.fail(cmd, "no matrix saved by <matrixsave>");
        matrix_ = saved_matrices_.back();
        saved_matrices_.pop_back();
    } else if (name == "newvar" || name == "newvarcte") {
        defineVariables(cmd, name == "newvarcte", false);
    } else if (name == "setvar") {
        defineVariables(cmd, false, true);
    } else if (name == "runlist") {
        src_.checkAttributes(cmd, {"name", "times"});
        const std::string list = src_.text(cmd, "name");
        const int times = src_.integer(cmd, "times", ev_, 1);
        pugi::xml_node target = commands_.find_child_by_attribute("list", "name", list.c_str());
        if (!target) src_.fail(cmd, "name=\"" + list + "\": no <list name=\"" + list + "\"> in <commands>");
        for (int i = 0; i < times; ++i) runList(target, depth + 1);
    } else if (name == "drawbox" || name == "drawcylinder" || name == "drawsphere" || name == "fillbox") {
        if (!mk_chosen_) src_.fail(cmd, "draws before any setmkfluid, setmkbound or setmkvoid");
        if (name == "drawbox") drawBoxCommand(cmd);
        else if (name == "fillbox") fillBoxCommand(cmd);
        else drawRoundCommand(cmd, name == "drawcylinder");
    } else {
        src_.fail(cmd, "is not a command SeaSpring's gencase supports. Supported: setmkfluid, "
                       "setmkbound, setmkvoid, setdrawmode, setshapemode, setactive, "
                       "setnormalinvert, resetdraw, drawbox, drawcylinder, drawsphere, fillbox, "
                       "move, rotate, matrixreset, matrixsave, matrixload, newvar, newvarcte, "
                       "setvar, runlist, shapeout (see docs/case-format.md)");
    }
}

}  // namespace seaspring::gencase
