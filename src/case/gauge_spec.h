// SeaSpring — MIT licence.
/// \file gauge_spec.h
/// \brief `<special><gauges>`: DualSPHysics' gauge definitions (velocity, swl, maxz, force)
///        plus SeaSpring's pressure and solid-marker gauges, read into plain specs.
///
/// gencase reads the definition (expressions allowed, coefdp/coefh turned into lengths) and
/// writes the gauges into the resolved case in the same syntax with plain numbers
/// (writeGauges); the solver reads that back with the same parser (readGauges). Each gauge may override
/// the `<default>` timing (computedt, computetime, output, outputdt, outputtime; unset: the
/// DualSPHysics defaults, TimeOut and the whole run, output off).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "case/xml_source.h"
#include "core/vec3.h"

namespace seaspring::model {

enum class GaugeKind { Velocity, Pressure, Swl, MaxZ, Force, SolidMarker };

/// "velocity", "pressure", ... (the XML element name).
const char* gaugeElementName(GaugeKind k);

/// Timing of a gauge or of `<default>`; unset members fall back (gauge -> default -> DualSPHysics).
struct GaugeTiming {
    std::optional<double> computedt;                     ///< [s]; 0: every step
    std::optional<double> compute_start, compute_end;    ///< [s]
    std::optional<bool> output;                          ///< write the CSV
    std::optional<double> outputdt;                      ///< [s]; 0: every computed value
    std::optional<double> output_start, output_end;      ///< [s]
    std::optional<bool> savevtkpart;                     ///< accepted, not implemented (noted)
};

struct GaugeSpec {
    GaugeKind kind = GaugeKind::Velocity;
    std::string name;
    int line = 0;  ///< line of the element
    GaugeTiming timing;
    Vec3d point{0, 0, 0};                  ///< velocity, pressure, solidmarker
    Vec3d point0{0, 0, 0}, point2{0, 0, 0};  ///< swl line; maxz: point0 is the bottom point
    double pointdp = 0;                    ///< swl: spacing of the points [m]
    std::optional<double> masslimit;       ///< swl: [kg]
    std::optional<double> masslimit_coef;  ///< swl: masslimit = coef * massfluid
    double height = 0, distlimit = 0;      ///< maxz [m]
    double kclimit = 0.5;                  ///< velocity, pressure: least sum V W for a value
    int target_mkbound = -1;               ///< force (required), solidmarker (optional)
};

struct GaugeSet {
    GaugeTiming defaults;
    std::vector<GaugeSpec> gauges;
    bool empty() const { return gauges.empty(); }
};

/// Reads `<gauges>` (absent node: empty set). `dp` and `h` turn coefdp/coefh into lengths.
/// Errors name the file, line, element and value.
GaugeSet parseGauges(const XmlSource& src, pugi::xml_node gauges, const ValueEvaluator& ev, double dp,
                     double h);
/// parseGauges on the resolved case (plain numbers).
GaugeSet readGauges(const XmlSource& src, pugi::xml_node gauges, double dp, double h);

/// Writes `set` as a `<gauges>` child of `parent` (plain numbers, lengths resolved).
void writeGauges(const GaugeSet& set, pugi::xml_node parent);

}  // namespace seaspring::model
