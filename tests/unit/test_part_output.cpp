// SeaSpring — MIT licence.
/// \file test_part_output.cpp
/// \brief The solver's output files: part_NNNN.h5 round trips, layout and error paths, the
///        particle masses and case constants for ParaView's SPH filters, and the XDMF series
///        parts.xdmf (well-formed, counts, times, paths, types matching the HDF5).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <pugixml.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/id_order.h"
#include "error_expect.h"
#include "part_test_util.h"
#include "io/h5_util.h"
#include "io/part_output.h"
#include "io/part_writer.h"
#include "io/xdmf_series.h"

namespace seaspring::io {
namespace {

namespace fs = std::filesystem;

using test::errorOf;
using test::Particles;
using test::Scratch;
using test::makeParticles;
using test::sameBytes;


TEST(PartOutput, RoundTripIsByteExact) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    const Particles p = makeParticles();
    const double time = 0.1 + 0.2;  // 0.30000000000000004: must survive exactly
    const std::string rel = writePartH5(dir, p.frame(3, time, 123456789012LL));
    EXPECT_EQ(rel, "data/part_0003.h5");
    EXPECT_TRUE(fs::is_regular_file(fs::path(dir) / rel));
    EXPECT_FALSE(fs::exists(fs::path(dir) / "data/part_0003.h5.tmp"));

    const PartData d = readPartH5((fs::path(dir) / rel).string());
    EXPECT_EQ(d.np(), 5u);
    EXPECT_EQ(std::memcmp(&d.time, &time, sizeof time), 0) << d.time;
    EXPECT_EQ(d.step, 123456789012LL);
    EXPECT_TRUE(sameBytes(d.pos, p.pos));
    EXPECT_TRUE(sameBytes(d.vel, p.vel));
    EXPECT_TRUE(sameBytes(d.rhop, p.rhop));
    EXPECT_TRUE(sameBytes(d.press, p.press));
    EXPECT_EQ(d.id, p.id);
    EXPECT_EQ(d.type, p.type);
    EXPECT_EQ(d.mk, p.mk);
    EXPECT_EQ(d.excluded, p.excluded);
    EXPECT_TRUE(sameBytes(d.mass, p.mass));
}

TEST(PartOutput, FileNamesHaveAtLeastFourDigits) {
    EXPECT_EQ(partFileName(0), "data/part_0000.h5");
    EXPECT_EQ(partFileName(42), "data/part_0042.h5");
    EXPECT_EQ(partFileName(9999), "data/part_9999.h5");
    EXPECT_EQ(partFileName(12345), "data/part_12345.h5");
    EXPECT_HAS(errorOf([] { partFileName(-1); }), "index -1 is negative");
}

/// HDF5 layout of dataset `name` in `file` (H5D_CONTIGUOUS, H5D_CHUNKED, ...).
H5D_layout_t layoutOf(const h5::File& file, const char* name) {
    const hid_t set = H5Dopen2(file.id(), name, H5P_DEFAULT);
    EXPECT_GE(set, 0) << name;
    const hid_t dcpl = H5Dget_create_plist(set);
    const H5D_layout_t layout = H5Pget_layout(dcpl);
    H5Pclose(dcpl);
    H5Dclose(set);
    return layout;
}

void expectLayout(const std::string& path, std::size_t np) {
    h5::File file = h5::File::openReadOnly(path);
    EXPECT_EQ(h5::readStringAttribute(file, "format"), "SeaSpring part");
    EXPECT_EQ(h5::readInt64Attribute(file, "format_version"), 2);
    EXPECT_EQ(h5::readInt64Attribute(file, "np"), static_cast<std::int64_t>(np));
    const std::map<std::string, std::size_t> cols = {{"pos", 3}, {"vel", 3}, {"rhop", 1},
                                                     {"press", 1}, {"id", 1}, {"type", 1},
                                                     {"mk", 1}, {"excluded", 1}, {"mass", 1}};
    for (const auto& [name, c] : cols) {
        const h5::DatasetShape s = h5::datasetShape(file, name);
        EXPECT_EQ(s.rank, c == 1 ? 1 : 2) << name;
        EXPECT_EQ(s.rows, np) << name;
        EXPECT_EQ(s.cols, c) << name;
        EXPECT_EQ(layoutOf(file, name.c_str()), H5D_CONTIGUOUS) << name;
    }
}

TEST(PartOutput, DatasetsAreContiguousWithTheDocumentedShapes) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    const Particles p = makeParticles();
    const std::string rel = writePartH5(dir, p.frame(0, 0.0, 0));
    expectLayout((fs::path(dir) / rel).string(), 5);
}

TEST(PartOutput, ZeroParticlesWithoutArrays) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    PartFrame f;  // np = 0, every pointer nullptr
    f.index = 7;
    f.time = 2.5;
    f.step = 10;
    const std::string rel = writePartH5(dir, f);
    EXPECT_EQ(rel, "data/part_0007.h5");
    const std::string path = (fs::path(dir) / rel).string();
    expectLayout(path, 0);
    const PartData d = readPartH5(path);
    EXPECT_EQ(d.np(), 0u);
    EXPECT_EQ(d.time, 2.5);
    EXPECT_EQ(d.step, 10);
    EXPECT_TRUE(d.pos.empty() && d.vel.empty() && d.rhop.empty() && d.press.empty());
    EXPECT_TRUE(d.type.empty() && d.mk.empty() && d.excluded.empty() && d.mass.empty());
}

TEST(PartOutput, MassAndCaseConstantsForParaViewsSphFilters) {
    // A 2D case: walls, solid and fluid have different masses (massbound, rho_S dp^2, massfluid).
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    Particles p = makeParticles();
    p.type = {0, 0, 2, 3, 3};
    p.mass = {2.5e-3f, 2.5e-3f, 6.75e-3f, 2.4e-3f, 2.4e-3f};
    p.constants = {0.0070711, 0.005, "cubic spline", 998.5, 2, 161234.5};
    const std::string path = (fs::path(dir) / writePartH5(dir, p.frame(2, 0.25, 40))).string();
    {  // as ParaView and h5py see them: a float32 dataset [np] and scalar root attributes
        h5::File file = h5::File::openReadOnly(path);
        EXPECT_EQ(h5::datasetShape(file, "mass").rank, 1);
        EXPECT_EQ(h5::readDataset<float>(file, "mass"), p.mass);
        EXPECT_EQ(h5::readDoubleAttribute(file, "h"), 0.0070711);
        EXPECT_EQ(h5::readDoubleAttribute(file, "dp"), 0.005);
        EXPECT_EQ(h5::readStringAttribute(file, "kernel"), "cubic spline");
        EXPECT_EQ(h5::readDoubleAttribute(file, "rhop0"), 998.5);
        EXPECT_EQ(h5::readInt64Attribute(file, "dimension"), 2);
    }
    const PartData d = readPartH5(path);
    EXPECT_EQ(d.mass, p.mass);
    EXPECT_NE(d.mass[0], d.mass[3]);  // boundary and fluid
    EXPECT_EQ(d.constants.h, 0.0070711);
    EXPECT_EQ(d.constants.dp, 0.005);
    EXPECT_EQ(d.constants.kernel, "cubic spline");
    EXPECT_EQ(d.constants.rhop0, 998.5);
    EXPECT_EQ(d.constants.dimension, 2);
    EXPECT_EQ(d.constants.b, 161234.5);

    // A frame without masses is refused like any other missing array.
    PartFrame f = p.frame(3, 0.5, 80);
    f.mass = nullptr;
    EXPECT_HAS(errorOf([&] { writePartH5(dir, f); }), "dataset /mass: no data given for 5 rows");

    // A version 1 file (before /mass and the constants) still reads, without them.
    {
        h5::File file = h5::File::openReadWrite(path);
        h5::writeInt64Attribute(file, "format_version", 1);
        file.removeChild("mass");
        file.close();
    }
    const PartData old = readPartH5(path);
    EXPECT_EQ(old.mk, p.mk);
    EXPECT_TRUE(old.mass.empty());
    EXPECT_EQ(old.constants.h, 0.0);
    EXPECT_EQ(old.constants.kernel, "");
}

TEST(PartOutput, RewritingAnIndexReplacesTheFile) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    Particles p = makeParticles();
    writePartH5(dir, p.frame(1, 1.0, 1));
    p.rhop[0] = 1234.5f;
    const std::string rel = writePartH5(dir, p.frame(1, 2.0, 2));
    const PartData d = readPartH5((fs::path(dir) / rel).string());
    EXPECT_EQ(d.time, 2.0);
    EXPECT_EQ(d.rhop[0], 1234.5f);
}

TEST(PartOutput, MissingArrayFailsAndLeavesNoFile) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    const Particles p = makeParticles();
    PartFrame f = p.frame(0, 0.0, 0);
    f.mk = nullptr;
    const std::string msg = errorOf([&] { writePartH5(dir, f); });
    EXPECT_HAS(msg, "part_0000.h5.tmp");
    EXPECT_HAS(msg, "dataset /mk: no data given for 5 rows");
    EXPECT_FALSE(fs::exists(fs::path(dir) / "data/part_0000.h5"));
    EXPECT_FALSE(fs::exists(fs::path(dir) / "data/part_0000.h5.tmp"));
}

TEST(PartOutput, UnwritableOutputFolderIsReported) {
    // Tests may run as root, who may write anywhere: block the folders with plain files.
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    const Particles p = makeParticles();
    const std::string blocked_outdir = (fs::path(dir) / "outdir_is_a_file").string();
    std::ofstream(blocked_outdir) << "x";
    const std::string msg1 = errorOf([&] { writePartH5(blocked_outdir, p.frame(0, 0.0, 0)); });
    EXPECT_HAS(msg1, blocked_outdir + "/data: cannot create the output folder");

    // data/part_0000.h5.tmp cannot be created because data/ holds a folder of that name.
    const std::string outdir = (fs::path(dir) / "run").string();
    fs::create_directories(fs::path(outdir) / "data/part_0000.h5.tmp");
    const std::string msg2 = errorOf([&] { writePartH5(outdir, p.frame(0, 0.0, 0)); });
    EXPECT_HAS(msg2, "data/part_0000.h5.tmp: cannot create the part file: Is a directory");
    EXPECT_FALSE(fs::exists(fs::path(outdir) / "data/part_0000.h5"));

    // The rename fails when a non-empty folder stands where the finished file goes.
    fs::create_directories(fs::path(outdir) / "data/part_0001.h5/inside");
    const std::string msg3 = errorOf([&] { writePartH5(outdir, p.frame(1, 0.0, 0)); });
    EXPECT_HAS(msg3, "data/part_0001.h5: cannot rename the finished part file into place");
    EXPECT_FALSE(fs::exists(fs::path(outdir) / "data/part_0001.h5.tmp"));

    EXPECT_HAS(errorOf([&] { writePartH5(outdir, p.frame(-3, 0.0, 0)); }), "-3 is negative");
}

TEST(PartOutput, ReaderRejectsOtherFilesAndBrokenShapes) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    EXPECT_HAS(errorOf([&] { readPartH5(dir + "/none.h5"); }),
               "none.h5: cannot open file: No such file or directory");

    const Particles p = makeParticles();
    const std::string path = (fs::path(dir) / writePartH5(dir, p.frame(0, 0.0, 0))).string();
    {
        h5::File file = h5::File::openReadWrite(path);
        h5::writeStringAttribute(file, "format", "seaspring-case");
        file.close();
    }
    EXPECT_HAS(errorOf([&] { readPartH5(path); }),
               "attribute 'format' of /: is \"seaspring-case\", expected \"SeaSpring part\"");
    {
        h5::File file = h5::File::openReadWrite(path);
        h5::writeStringAttribute(file, "format", "SeaSpring part");
        h5::writeInt64Attribute(file, "format_version", 3);
        file.close();
    }
    EXPECT_HAS(errorOf([&] { readPartH5(path); }), "'format_version' of /: is 3, this code reads versions 1 to 2");
    {
        h5::File file = h5::File::openReadWrite(path);
        h5::writeInt64Attribute(file, "format_version", 2);
        file.removeChild("press");
        const std::vector<float> short_press = {1.0f, 2.0f};
        h5::writeDataset(file, "press", short_press);
        file.close();
    }
    EXPECT_HAS(errorOf([&] { readPartH5(path); }),
               "dataset /press: has shape [2], expected [5]");
    {
        h5::File file = h5::File::openReadWrite(path);
        file.removeChild("press");
        const std::vector<double> wrong_type(5, 1.0);
        h5::writeDataset(file, "press", wrong_type);
        file.close();
    }
    EXPECT_HAS(errorOf([&] { readPartH5(path); }),
               "dataset /press: has element type float64, expected float32");
}

// ---- XDMF series --------------------------------------------------------------------------

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

pugi::xml_node onlyChild(const pugi::xml_node& node, const char* name) {
    pugi::xml_node child = node.child(name);
    EXPECT_TRUE(child) << "no <" << name << "> in <" << node.name() << ">";
    EXPECT_FALSE(child.next_sibling(name)) << "several <" << name << ">";
    return child;
}

struct FrameInfo {
    std::string file;
    double time;
    std::size_t np;
};

/// Parses parts.xdmf and checks its structure against `frames`.
void expectSeries(const std::string& path, const std::vector<FrameInfo>& frames) {
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_file(path.c_str());
    ASSERT_TRUE(parsed) << parsed.description() << " at offset " << parsed.offset;
    const pugi::xml_node xdmf = onlyChild(doc, "Xdmf");
    EXPECT_STREQ(xdmf.attribute("Version").value(), "3.0");
    const pugi::xml_node collection = onlyChild(onlyChild(xdmf, "Domain"), "Grid");
    EXPECT_STREQ(collection.attribute("GridType").value(), "Collection");
    EXPECT_STREQ(collection.attribute("CollectionType").value(), "Temporal");

    std::size_t n = 0;
    for (pugi::xml_node grid : collection.children("Grid")) {
        ASSERT_LT(n, frames.size()) << "more frames than added";
        const FrameInfo& want = frames[n++];
        const std::string np = std::to_string(want.np);
        EXPECT_STREQ(grid.attribute("GridType").value(), "Uniform");
        const char* time_text = onlyChild(grid, "Time").attribute("Value").value();
        EXPECT_EQ(std::strtod(time_text, nullptr), want.time) << time_text;  // exact
        const pugi::xml_node topo = onlyChild(grid, "Topology");
        EXPECT_STREQ(topo.attribute("TopologyType").value(), "Polyvertex");
        EXPECT_EQ(topo.attribute("NumberOfElements").value(), np);
        EXPECT_STREQ(topo.attribute("NodesPerElement").value(), "1");
        const pugi::xml_node conn = onlyChild(topo, "DataItem");  // vertex cells: ParaView shows them
        EXPECT_EQ(std::string(conn.child_value()), want.file + ":/id");
        EXPECT_EQ(conn.attribute("Dimensions").value(), np);
        const pugi::xml_node geo = onlyChild(grid, "Geometry");
        EXPECT_STREQ(geo.attribute("GeometryType").value(), "XYZ");
        const pugi::xml_node pos = onlyChild(geo, "DataItem");
        EXPECT_EQ(pos.attribute("Dimensions").value(), np + " 3");
        EXPECT_STREQ(pos.attribute("NumberType").value(), "Float");
        EXPECT_STREQ(pos.attribute("Precision").value(), "8");
        EXPECT_STREQ(pos.attribute("Format").value(), "HDF");
        EXPECT_EQ(std::string(pos.child_value()), want.file + ":/pos");

        std::vector<std::string> names;
        for (pugi::xml_node a : grid.children("Attribute")) {
            names.push_back(a.attribute("Name").value());
            EXPECT_STREQ(a.attribute("Center").value(), "Node");
            const pugi::xml_node item = onlyChild(a, "DataItem");
            const bool vector = names.back() == "vel";
            EXPECT_STREQ(a.attribute("AttributeType").value(), vector ? "Vector" : "Scalar");
            EXPECT_EQ(item.attribute("Dimensions").value(), vector ? np + " 3" : np);
            EXPECT_EQ(std::string(item.child_value()), want.file + ":/" + names.back());
        }
        EXPECT_EQ(names, (std::vector<std::string>{"vel", "rhop", "press", "type", "mk", "id",
                                                   "excluded", "mass"}));
    }
    EXPECT_EQ(n, frames.size());
}

TEST(XdmfSeries, ThreeFramesWellFormedWithCountsTimesAndPaths) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    XdmfSeries series(dir);
    EXPECT_EQ(series.path(), (fs::path(dir) / "parts.xdmf").string());
    EXPECT_FALSE(fs::exists(series.path()));  // nothing before the first add

    const std::vector<FrameInfo> frames = {
        {"data/part_0000.h5", 0.0, 5},
        {"data/part_0001.h5", 0.1, 0},          // %.17g: 0.10000000000000001
        {"data/part_0002.h5", 1.0 / 3.0, 171496},
    };
    for (std::size_t i = 0; i < frames.size(); ++i) {
        series.add(frames[i].file, frames[i].time, frames[i].np);
        EXPECT_EQ(series.frameCount(), i + 1);
        // After every add the file holds all frames so far and is complete on its own.
        expectSeries(series.path(), std::vector<FrameInfo>(frames.begin(),
                                                           frames.begin() + long(i) + 1));
        EXPECT_FALSE(fs::exists(series.path() + ".tmp"));
    }
    EXPECT_HAS(readAll(series.path()), "<Time Value=\"0.33333333333333331\"/>");
}

TEST(XdmfSeries, NumberTypesMatchThePartFile) {
    // Every DataItem's NumberType/Precision/Dimensions must describe the HDF5 dataset it names.
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    const Particles p = makeParticles();
    XdmfSeries series(dir);
    series.add(writePartH5(dir, p.frame(0, 0.5, 7)), 0.5, p.id.size());

    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_file(series.path().c_str()));
    h5::File file = h5::File::openReadOnly((fs::path(dir) / "data/part_0000.h5").string());
    int checked = 0;
    for (const pugi::xpath_node& x : doc.select_nodes("//DataItem")) {
        const pugi::xml_node item = x.node();
        const std::string text = item.child_value();
        const std::string dataset = text.substr(text.find(":/") + 2);
        const hid_t set = H5Dopen2(file.id(), dataset.c_str(), H5P_DEFAULT);
        ASSERT_GE(set, 0) << dataset;
        const hid_t type = H5Dget_type(set);
        const std::string number = item.attribute("NumberType").value();
        const H5T_class_t cls = H5Tget_class(type);
        if (number == "Float") {
            EXPECT_EQ(cls, H5T_FLOAT) << dataset;
        } else {
            EXPECT_EQ(cls, H5T_INTEGER) << dataset;
            EXPECT_EQ(H5Tget_sign(type), H5T_SGN_NONE) << dataset;
            EXPECT_TRUE(number == "UInt" || number == "UChar") << number;
        }
        EXPECT_EQ(std::to_string(H5Tget_size(type)), item.attribute("Precision").value())
            << dataset;
        if (number == "UChar") {
            EXPECT_EQ(H5Tget_size(type), 1u) << dataset;
        }
        const h5::DatasetShape s = h5::datasetShape(file, dataset);
        const std::string dims =
            std::to_string(s.rows) + (s.rank == 2 ? " " + std::to_string(s.cols) : "");
        EXPECT_EQ(dims, item.attribute("Dimensions").value()) << dataset;
        H5Tclose(type);
        H5Dclose(set);
        ++checked;
    }
    EXPECT_EQ(checked, 10);  // the connectivity (/id), pos + 8 attributes
}

TEST(XdmfSeries, SpecialCharactersInPathsAreEscaped) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    XdmfSeries series(dir);
    series.add("data/a&b<c>\"d'.h5", 1.0, 2);
    expectSeries(series.path(), {{"data/a&b<c>\"d'.h5", 1.0, 2}});
    EXPECT_HAS(readAll(series.path()), "data/a&amp;b&lt;c&gt;&quot;d&apos;.h5:/pos");
}

TEST(XdmfSeries, ErrorsKeepTheSeriesConsistent) {
    const Scratch scratch;
    const std::string& dir = scratch.dir;
    XdmfSeries series(dir);
    series.add("data/part_0000.h5", 0.0, 1);
    EXPECT_HAS(errorOf([&] { series.add("data/part_0001.h5", std::nan(""), 1); }),
               "parts.xdmf: frame data/part_0001.h5: time nan is not finite");
    EXPECT_HAS(errorOf([&] { series.add("", 1.0, 1); }), "parts.xdmf: empty part file path");
    EXPECT_EQ(series.frameCount(), 1u);
    expectSeries(series.path(), {{"data/part_0000.h5", 0.0, 1}});

    XdmfSeries missing((fs::path(dir) / "no_such_folder").string());
    const std::string msg = errorOf([&] { missing.add("data/part_0000.h5", 0.0, 1); });
    EXPECT_HAS(msg, "no_such_folder/parts.xdmf: cannot write the file (creating ");
    EXPECT_HAS(msg, "No such file or directory");
    EXPECT_EQ(missing.frameCount(), 0u);
}

}  // namespace
}  // namespace seaspring::io
