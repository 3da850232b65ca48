// SeaSpring — MIT licence.
/// \file command_runner.h
/// \brief Runs GenCase `<commands>` (`<mainlist>` and named `<list>`s) on the lattice.
///
/// GenCase is a small state machine: the current MK (`setmkfluid`, `setmkbound`,
/// `setmkvoid`), the draw mode, the transform (`move`, `rotate`, `matrix*`) and whether
/// points are drawn at all (`setactive`). Drawing commands paint the current MK on the
/// lattice; later drawing replaces earlier drawing. While shapes are drawn
/// (`<setactive drawshapes="1"/>`) `<drawbox>` also records its faces (shape_set.h), which
/// `<shapeout file="X"/>` collects into the shape set X (for `<normals>`).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "case/xml_source.h"
#include "gencase/expression.h"
#include "gencase/lattice_grid.h"
#include "gencase/shape_set.h"
#include "gencase/shapes.h"

namespace seaspring::gencase {

using model::XmlSource;

struct MkConfig {
    int fluidcount = 9;
    int boundcount = 240;
    std::uint16_t fluidMk(int mkfluid) const { return std::uint16_t(mkfluid + 1); }
    std::uint16_t boundMk(int mkbound) const { return std::uint16_t(mkbound + fluidcount + 1); }
    bool isFluid(std::uint16_t mk) const { return mk >= 1 && mk <= fluidcount; }
};

class CommandRunner {
public:
    CommandRunner(const XmlSource& src, ExpressionEvaluator& ev, LatticeGrid& grid, MkConfig mk,
                  std::ostream& log, bool verbose);

    /// Runs the `<mainlist>` of a `<commands>` element (named lists become callable).
    void run(pugi::xml_node commands);

    /// Evaluates `newvar`/`newvarcte`/`setvar` attributes (also used for `<predefinition>`).
    void defineVariables(pugi::xml_node node, bool constant, bool assign);

    /// The shape sets named by `<shapeout>`, in the order first written (a later
    /// `<shapeout>` of the same name replaces the set's faces).
    const std::vector<ShapeSet>& shapeSets() const { return shape_sets_; }

private:
    void runList(pugi::xml_node list, int depth);
    void runCommand(pugi::xml_node cmd, int depth);
    void drawBoxCommand(pugi::xml_node cmd);
    void drawRoundCommand(pugi::xml_node cmd, bool cylinder);
    void fillBoxCommand(pugi::xml_node cmd);
    /// Layer offsets of `<layers vdp>` (in dp); `marked` receives which carry GenCase's '*'.
    std::vector<double> layers(pugi::xml_node cmd, std::vector<bool>* marked = nullptr) const;
    /// True when the current drawing command also records shapes (drawshapes on and the
    /// current MK's kind selected by <setshapemode>).
    bool recordsShapes(pugi::xml_node cmd) const;
    /// Records the faces of one layer of a drawbox; returns how many.
    std::size_t recordBoxShape(pugi::xml_node cmd, Vec3d lo, Vec3d hi, unsigned faces, double vdp);
    void setShapeMode(pugi::xml_node cmd);
    void shapeOut(pugi::xml_node cmd);
    void boxExtent(pugi::xml_node cmd, Vec3d& p0, Vec3d& size) const;
    void report(pugi::xml_node cmd, std::size_t count);

    const XmlSource& src_;
    ExpressionEvaluator& ev_;
    LatticeGrid& grid_;
    MkConfig mkcfg_;
    std::ostream& log_;
    bool verbose_;
    pugi::xml_node commands_;

    std::uint16_t mk_ = 0;  ///< current global MK, 0 = void
    bool mk_chosen_ = false;
    DrawMode mode_ = DrawMode::Full;
    Affine matrix_;
    std::vector<Affine> saved_matrices_;
    bool draw_points_ = true;
    bool draw_shapes_ = false;    ///< <setactive drawshapes>
    bool normal_invert_ = false;  ///< <setnormalinvert invert>
    bool shape_actual_ = true;    ///< <setshapemode> selects the actual geometry
    unsigned shape_kinds_ = 7;    ///< <setshapemode> MK kinds: 1 bound, 2 fluid, 4 void
    std::vector<ShapeFace> pending_faces_;  ///< recorded since the last <shapeout>
    int pending_first_line_ = 0;            ///< line of the first command that recorded them
    std::vector<ShapeSet> shape_sets_;
    std::uint64_t commands_run_ = 0;  ///< commands run so far, runlist repetitions counted
};

/// Parses a `<boxfill>` text ("solid", "all^top", "bottom | left | right") into BoxFaces.
unsigned parseBoxFill(const std::string& text, bool& ok);

}  // namespace seaspring::gencase
