// SeaSpring — MIT licence.
/// \file xdmf_series.cpp
#include "io/xdmf_series.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace seaspring::io {

namespace fs = std::filesystem;

XdmfSeries::XdmfSeries(std::string outdir)
    : outdir_(std::move(outdir)), path_((fs::path(outdir_) / "parts.xdmf").string()) {}

namespace {
void attribute(std::ostream& os, const char* name, const char* type, const char* number, int precision,
               const std::string& file, std::size_t np, int cols) {
    os << "        <Attribute Name=\"" << name << "\" AttributeType=\"" << type << "\" Center=\"Node\">\n"
       << "          <DataItem Dimensions=\"" << np;
    if (cols > 1) os << " " << cols;
    os << "\" NumberType=\"" << number << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << file << ":/"
       << name << "</DataItem>\n        </Attribute>\n";
}
}  // namespace

void XdmfSeries::add(const std::string& file, double time, std::size_t np) {
    frames_.push_back({file, time, np});
    std::ostringstream os;
    os << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
       << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    char t[40];
    for (const Frame& f : frames_) {
        std::snprintf(t, sizeof t, "%.17g", f.time);
        os << "      <Grid Name=\"part\" GridType=\"Uniform\">\n        <Time Value=\"" << t << "\" />\n"
           << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << f.np
           << "\" NodesPerElement=\"1\" />\n"
           << "        <Geometry GeometryType=\"XYZ\">\n          <DataItem Dimensions=\"" << f.np
           << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << f.file << ":/pos</DataItem>\n"
           << "        </Geometry>\n";
        attribute(os, "vel", "Vector", "Float", 4, f.file, f.np, 3);
        attribute(os, "rhop", "Scalar", "Float", 4, f.file, f.np, 1);
        attribute(os, "press", "Scalar", "Float", 4, f.file, f.np, 1);
        attribute(os, "type", "Scalar", "UChar", 1, f.file, f.np, 1);
        attribute(os, "mk", "Scalar", "UInt", 2, f.file, f.np, 1);
        attribute(os, "id", "Scalar", "UInt", 4, f.file, f.np, 1);
        attribute(os, "excluded", "Scalar", "UChar", 1, f.file, f.np, 1);
        os << "      </Grid>\n";
    }
    os << "    </Grid>\n  </Domain>\n</Xdmf>\n";
    const std::string tmp = path_ + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << os.str();
        if (!out) throw Error(tmp + ": cannot write the XDMF series");
    }
    std::error_code ec;
    fs::rename(tmp, path_, ec);
    if (ec) throw Error(path_ + ": cannot write: " + ec.message());
}

}  // namespace seaspring::io
