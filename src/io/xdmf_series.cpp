// SeaSpring — MIT licence.
/// \file xdmf_series.cpp
/// \brief Writing the XDMF 3 temporal collection parts.xdmf.
#include "io/xdmf_series.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "io/json_writer.h"

namespace seaspring::io {
namespace {

/// One node attribute of the part file and how XDMF is to read it.
struct AttributeSpec {
    const char* name;
    const char* attribute_type;  ///< "Scalar" or "Vector"
    const char* number_type;     ///< XDMF NumberType: Float, UInt, UChar
    int precision;               ///< bytes per component
    int components;              ///< 1 or 3
};

/// The datasets of part_output.h other than /pos, with their HDF5 element types.
constexpr AttributeSpec kAttributes[] = {
    {"vel", "Vector", "Float", 4, 3},   {"rhop", "Scalar", "Float", 4, 1},
    {"press", "Scalar", "Float", 4, 1}, {"type", "Scalar", "UChar", 1, 1},
    {"mk", "Scalar", "UInt", 2, 1},     {"id", "Scalar", "UInt", 4, 1},
    {"excluded", "Scalar", "UChar", 1, 1}, {"mass", "Scalar", "Float", 4, 1},
};
/// The solid fields (cases with VCPM solids).
constexpr AttributeSpec kSolidAttributes[] = {
    {"disp", "Vector", "Float", 4, 3}, {"strain", "Scalar", "Float", 4, 1}, {"broken", "Scalar", "UChar", 1, 1},
    {"damage", "Scalar", "Float", 4, 1},
};

/// `text` with the five XML special characters replaced by entities.
std::string xmlEscape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

/// `<DataItem ...>FILE:/DATASET</DataItem>` for an [np] or [np x components] dataset.
std::string dataItem(const std::string& file, const char* dataset, std::size_t np,
                     int components, const char* number_type, int precision) {
    std::string dims = std::to_string(np);
    if (components > 1) dims += " " + std::to_string(components);
    return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + number_type +
           "\" Precision=\"" + std::to_string(precision) + "\" Format=\"HDF\">" + file + ":/" +
           dataset + "</DataItem>";
}

/// The Uniform grid of one frame, indented for its place in the collection.
std::string attributeXml(const std::string& file, const AttributeSpec& a, std::size_t np) {
    return "        <Attribute Name=\"" + std::string(a.name) + "\" AttributeType=\"" + a.attribute_type +
           "\" Center=\"Node\">\n          " + dataItem(file, a.name, np, a.components, a.number_type, a.precision) +
           "\n        </Attribute>\n";
}

std::string frameXml(const std::string& h5_file, double time, std::size_t np, bool solids) {
    const std::string file = xmlEscape(h5_file);
    char time_text[40];
    std::snprintf(time_text, sizeof time_text, "%.17g", time);
    std::string stem = std::filesystem::path(h5_file).stem().string();
    std::string x;
    x += "      <Grid Name=\"" + xmlEscape(stem) + "\" GridType=\"Uniform\">\n";
    x += "        <Time Value=\"" + std::string(time_text) + "\"/>\n";
    // One vertex cell per particle: /id is the particle index (part files are in id order), so
    // it is the connectivity; without it ParaView reads the points but no cells and shows nothing.
    x += "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + std::to_string(np) +
         "\" NodesPerElement=\"1\">\n          " + dataItem(file, "id", np, 1, "UInt", 4) + "\n        </Topology>\n";
    x += "        <Geometry GeometryType=\"XYZ\">\n";
    x += "          " + dataItem(file, "pos", np, 3, "Float", 8) + "\n";
    x += "        </Geometry>\n";
    for (const AttributeSpec& a : kAttributes) x += attributeXml(file, a, np);
    if (solids)
        for (const AttributeSpec& a : kSolidAttributes) x += attributeXml(file, a, np);
    x += "      </Grid>\n";
    return x;
}

}  // namespace

XdmfSeries::XdmfSeries(std::string outdir)
    : outdir_(std::move(outdir)),
      path_((std::filesystem::path(outdir_) / "parts.xdmf").string()) {}

void XdmfSeries::add(const std::string& h5_relative_path, double time, std::size_t np, bool solids) {
    if (h5_relative_path.empty()) throw Error(formatLocation(path_, 0, "empty part file path"));
    if (!std::isfinite(time))
        throw Error(formatLocation(path_, 0, "frame " + h5_relative_path + ": time " +
                                                 std::to_string(time) + " is not finite"));
    frames_.push_back(frameXml(h5_relative_path, time, np, solids));

    std::string xml;
    xml += "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n";
    xml += "<Xdmf Version=\"3.0\">\n";
    xml += "  <Domain>\n";
    xml += "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const std::string& frame : frames_) xml += frame;
    xml += "    </Grid>\n";
    xml += "  </Domain>\n";
    xml += "</Xdmf>\n";
    try {
        writeTextFileAtomic(path_, xml);
    } catch (...) {
        frames_.pop_back();
        throw;
    }
}

}  // namespace seaspring::io
