// SeaSpring — MIT licence.
/// \file test_vtu_writer.cpp
/// \brief The VTU particle preview: exact XML header, appended block sizes and contents.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/error.h"
#include "error_expect.h"
#include "io/vtu_writer.h"

namespace seaspring::io {
namespace {

namespace fs = std::filesystem;

using test::errorOf;


ParticleSet makeParticles() {
    ParticleSet p;
    p.resize(3);
    p.id = {0, 1, 2};
    p.type = {ParticleType::Fixed, ParticleType::Solid, ParticleType::Fluid};
    p.mk = {12, 13, 1};
    p.pos = {{0.0, 0.0, 0.0}, {0.01, -0.0, 0.02}, {1.0 / 3.0, 2.0, -5.5}};
    p.vel = {{0.0f, 0.0f, 0.0f}, {0.5f, 0.0f, -0.25f}, {1.0f, 2.0f, 3.0f}};
    p.rhop = {1000.0f, 1000.5f, 999.75f};
    p.mass = {0.1f, 0.2f, 0.3f};
    return p;
}

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Splits the appended block into its arrays: each is a UInt64 byte count + bytes.
std::vector<std::string> appendedArrays(const std::string& binary) {
    std::vector<std::string> arrays;
    std::size_t at = 0;
    while (at < binary.size()) {
        std::uint64_t bytes = 0;
        if (at + 8 > binary.size()) break;
        std::memcpy(&bytes, binary.data() + at, 8);
        at += 8;
        if (at + bytes > binary.size()) break;
        arrays.push_back(binary.substr(at, bytes));
        at += bytes;
    }
    EXPECT_EQ(at, binary.size()) << "appended block does not split into whole arrays";
    return arrays;
}

template <typename T>
std::string bytesOf(const std::vector<T>& v) {
    return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

class VtuWriterTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(::testing::TempDir()) /
               ("seaspring_vtu_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string file(const std::string& name) const { return (dir_ / name).string(); }

    fs::path dir_;
};

const char* const kHeader3 =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
    "  <UnstructuredGrid>\n"
    "    <Piece NumberOfPoints=\"3\" NumberOfCells=\"3\">\n"
    "      <PointData>\n"
    "        <DataArray type=\"UInt32\" Name=\"id\" format=\"appended\" offset=\"0\"/>\n"
    "        <DataArray type=\"UInt8\" Name=\"type\" format=\"appended\" offset=\"20\"/>\n"
    "        <DataArray type=\"UInt16\" Name=\"mk\" format=\"appended\" offset=\"31\"/>\n"
    "        <DataArray type=\"Float32\" Name=\"vel\" NumberOfComponents=\"3\" format=\"appended\" offset=\"45\"/>\n"
    "        <DataArray type=\"Float32\" Name=\"rhop\" format=\"appended\" offset=\"89\"/>\n"
    "        <DataArray type=\"Float32\" Name=\"mass\" format=\"appended\" offset=\"109\"/>\n"
    "        <DataArray type=\"UInt8\" Name=\"bonds\" format=\"appended\" offset=\"129\"/>\n"
    "        <DataArray type=\"Float32\" Name=\"stress\" format=\"appended\" offset=\"140\"/>\n"
    "      </PointData>\n"
    "      <Points>\n"
    "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"appended\" offset=\"160\"/>\n"
    "      </Points>\n"
    "      <Cells>\n"
    "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"appended\" offset=\"240\"/>\n"
    "        <DataArray type=\"Int32\" Name=\"offsets\" format=\"appended\" offset=\"260\"/>\n"
    "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"280\"/>\n"
    "      </Cells>\n"
    "    </Piece>\n"
    "  </UnstructuredGrid>\n"
    "  <AppendedData encoding=\"raw\">\n"
    "_";
const char* const kFooter = "\n  </AppendedData>\n</VTKFile>\n";

TEST_F(VtuWriterTest, HeaderAndAppendedBlockAreExact) {
    const std::string path = file("particles.vtu");
    const ParticleSet p = makeParticles();
    const std::vector<std::uint8_t> bonds = {0, 18, 0};
    const std::vector<float> stress = {0.0f, 1.5e6f, -2.0f};
    writeParticlesVtu(path, p, {{"bonds", bonds}, {"stress", stress}});
    EXPECT_FALSE(fs::exists(path + ".tmp"));

    const std::string all = readAll(path);
    const std::string header = kHeader3;
    ASSERT_EQ(all.substr(0, header.size()), header);
    const std::string footer = kFooter;
    ASSERT_GE(all.size(), header.size() + footer.size());
    EXPECT_EQ(all.substr(all.size() - footer.size()), footer);
    // 12 arrays: 12 UInt64 counts + 3*(4+1+2+12+4+4+1+4+24+4+4+1) data bytes.
    const std::string binary = all.substr(header.size(), all.size() - header.size() - footer.size());
    ASSERT_EQ(binary.size(), 12u * 8u + 3u * 65u);

    const std::vector<std::string> arrays = appendedArrays(binary);
    ASSERT_EQ(arrays.size(), 12u);
    EXPECT_EQ(arrays[0], bytesOf(p.id));
    EXPECT_EQ(arrays[1], bytesOf(p.type));
    EXPECT_EQ(arrays[2], bytesOf(p.mk));
    EXPECT_EQ(arrays[3], bytesOf(p.vel));
    EXPECT_EQ(arrays[4], bytesOf(p.rhop));
    EXPECT_EQ(arrays[5], bytesOf(p.mass));
    EXPECT_EQ(arrays[6], bytesOf(bonds));
    EXPECT_EQ(arrays[7], bytesOf(stress));
    EXPECT_EQ(arrays[8], bytesOf(p.pos));
    EXPECT_EQ(arrays[9], bytesOf(std::vector<std::int32_t>{0, 1, 2}));    // connectivity
    EXPECT_EQ(arrays[10], bytesOf(std::vector<std::int32_t>{1, 2, 3}));   // offsets
    EXPECT_EQ(arrays[11], bytesOf(std::vector<std::uint8_t>{1, 1, 1}));   // VTK_VERTEX
}

TEST_F(VtuWriterTest, EmptyParticleSetGivesEmptyArrays) {
    const std::string path = file("empty.vtu");
    writeParticlesVtu(path, ParticleSet{});
    const std::string all = readAll(path);
    EXPECT_HAS(all, "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\">");
    EXPECT_HAS(all, "Name=\"types\" format=\"appended\" offset=\"72\"/>");
    const std::size_t start = all.find("<AppendedData encoding=\"raw\">\n_");
    ASSERT_NE(start, std::string::npos);
    const std::size_t data = start + std::strlen("<AppendedData encoding=\"raw\">\n_");
    const std::string footer = kFooter;
    EXPECT_EQ(all.size() - data - footer.size(), 10u * 8u);  // ten zero byte counts
    EXPECT_EQ(all.substr(data, 80), std::string(80, '\0'));
}

TEST_F(VtuWriterTest, OverwritesAnExistingFile) {
    const std::string path = file("p.vtu");
    std::ofstream(path) << "old contents";
    writeParticlesVtu(path, makeParticles());
    EXPECT_EQ(readAll(path).substr(0, 21), "<?xml version=\"1.0\"?>");
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(VtuWriterTest, ExtraArrayOfWrongLengthIsRejected) {
    const std::string path = file("p.vtu");
    EXPECT_HAS(errorOf([&] { writeParticlesVtu(path, makeParticles(), {{"clamp", std::vector<std::uint8_t>{1, 0}}}); }),
               path + ": VTU extra array 'clamp' has 2 values, expected one per particle (3)");
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(VtuWriterTest, BadExtraArrayNamesAreRejected) {
    const std::string path = file("p.vtu");
    const std::vector<float> v(3, 1.0f);
    EXPECT_HAS(errorOf([&] { writeParticlesVtu(path, makeParticles(), {{"mass", v}}); }),
               path + ": VTU array name 'mass' is used twice");
    EXPECT_HAS(errorOf([&] { writeParticlesVtu(path, makeParticles(), {{"a", v}, {"a", v}}); }),
               path + ": VTU array name 'a' is used twice");
    EXPECT_HAS(errorOf([&] { writeParticlesVtu(path, makeParticles(), {{"", v}}); }),
               path + ": VTU extra array with an empty name");
    EXPECT_HAS(errorOf([&] { writeParticlesVtu(path, makeParticles(), {{"a<b", v}}); }),
               path + ": VTU extra array name 'a<b' contains a character not allowed here");
}

TEST_F(VtuWriterTest, InconsistentParticleSetIsRejected) {
    const std::string path = file("p.vtu");
    ParticleSet p = makeParticles();
    p.mass.push_back(1.0f);
    EXPECT_HAS(errorOf([&] { writeParticlesVtu(path, p); }),
               path + ": particle array mass has 4 entries, expected 3 (size of id)");
}

TEST_F(VtuWriterTest, UnwritableDirectoryIsReported) {
    const std::string path = file("no_such_dir/p.vtu");
    EXPECT_HAS(errorOf([&] { writeParticlesVtu(path, makeParticles()); }),
               path + ": cannot create " + path + ".tmp: No such file or directory");
}

}  // namespace
}  // namespace seaspring::io
