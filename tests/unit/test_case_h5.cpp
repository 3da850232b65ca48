// SeaSpring — MIT licence.
/// \file test_case_h5.cpp
/// \brief Round trips and error paths of the HDF5 case file (io/case_h5) and h5_util.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/error.h"
#include "error_expect.h"
#include "io/case_h5.h"
#include "io/h5_util.h"

namespace seaspring::io {
namespace {

namespace fs = std::filesystem;

using test::errorOf;


template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// 6 particles: 2 fixed, 2 solid (or moving when !solids), 2 fluid, awkward float values.
ParticleSet makeParticles(bool solids) {
    ParticleSet p;
    p.resize(6);
    const ParticleType types[6] = {ParticleType::Fixed, ParticleType::Fixed,
                                   solids ? ParticleType::Solid : ParticleType::Moving,
                                   solids ? ParticleType::Solid : ParticleType::Moving,
                                   ParticleType::Fluid, ParticleType::Fluid};
    const double tiny = std::numeric_limits<double>::denorm_min();
    for (std::uint32_t i = 0; i < 6; ++i) {
        p.id[i] = i;
        p.type[i] = types[i];
        p.mk[i] = static_cast<std::uint16_t>(i < 4 ? 11 + i / 2 : 1);
        p.pos[i] = {0.1 * i, -0.0, 1.0 / 3.0 + i * tiny};
        p.vel[i] = {i == 5 ? -1.5e-40f : 0.0f, 0.25f * i, -7.0f};
        p.rhop[i] = 1000.0f + 0.1f * i;
        p.mass[i] = 1.0e-3f / 3.0f;
    }
    return p;
}

/// Solids are particles 2 and 3; particle 2 bonds to 3 and to clamps 0 and 1.
BondNetwork makeBonds() {
    BondNetwork b;
    b.first_solid = 2;
    b.offset = {0, 3, 4};
    b.neighbour = {3, 0, 1, 2};
    b.rest_length = {0.01, 0.01, 0.01 * std::sqrt(2.0), 0.01};
    b.kind = {BondFirst, BondFirst | BondClampFlag, BondSecond | BondClampFlag, BondFirst};
    return b;
}

CaseFileHeader makeHeader() { return {"dam_break", 3, 0.01, 6, "SeaSpring gencase test"}; }

class CaseH5Test : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(::testing::TempDir()) /
               ("seaspring_case_h5_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string file(const std::string& name) const { return (dir_ / name).string(); }

    /// Writes a valid file with bonds, then lets `amend` damage it.
    std::string damagedFile(const std::function<void(h5::File&)>& amend) {
        const std::string path = file("bad.h5");
        const ParticleSet p = makeParticles(true);
        const BondNetwork b = makeBonds();
        writeCaseH5(path, makeHeader(), p, &b);
        h5::File f = h5::File::openReadWrite(path);
        amend(f);
        f.close();
        return path;
    }

    fs::path dir_;
};

void expectSameParticles(const ParticleSet& a, const ParticleSet& b) {
    EXPECT_TRUE(sameBytes(a.id, b.id));
    EXPECT_TRUE(sameBytes(a.type, b.type));
    EXPECT_TRUE(sameBytes(a.mk, b.mk));
    EXPECT_TRUE(sameBytes(a.pos, b.pos));
    EXPECT_TRUE(sameBytes(a.vel, b.vel));
    EXPECT_TRUE(sameBytes(a.rhop, b.rhop));
    EXPECT_TRUE(sameBytes(a.mass, b.mass));
}

TEST_F(CaseH5Test, RoundTripWithoutBondsIsByteExact) {
    const std::string path = file("case.h5");
    const ParticleSet p = makeParticles(false);
    writeCaseH5(path, makeHeader(), p, nullptr);
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    const CaseFileContents c = readCaseH5(path);
    EXPECT_EQ(c.header.case_name, "dam_break");
    EXPECT_EQ(c.header.dimensions, 3);
    EXPECT_EQ(c.header.dp, 0.01);
    EXPECT_EQ(c.header.np, 6u);
    EXPECT_EQ(c.header.generator, "SeaSpring gencase test");
    EXPECT_FALSE(c.has_bonds);
    EXPECT_TRUE(c.bonds.offset.empty());
    expectSameParticles(c.particles, p);
    EXPECT_TRUE(std::signbit(c.particles.pos[0].y));  // -0.0 survived
}

TEST_F(CaseH5Test, RoundTripWithBondsIsByteExact) {
    const std::string path = file("case.h5");
    const ParticleSet p = makeParticles(true);
    const BondNetwork b = makeBonds();
    CaseFileHeader h = makeHeader();
    h.dimensions = 2;
    writeCaseH5(path, h, p, &b);
    const CaseFileContents c = readCaseH5(path);
    EXPECT_EQ(c.header.dimensions, 2);
    ASSERT_TRUE(c.has_bonds);
    expectSameParticles(c.particles, p);
    EXPECT_EQ(c.bonds.first_solid, 2u);
    EXPECT_EQ(c.bonds.offset, (std::vector<std::uint32_t>{0, 3, 4}));
    EXPECT_EQ(c.bonds.neighbour, (std::vector<std::uint32_t>{3, 0, 1, 2}));
    EXPECT_TRUE(sameBytes(c.bonds.rest_length, b.rest_length));
    EXPECT_EQ(c.bonds.kind, (std::vector<std::uint8_t>{0, 2, 3, 0}));
}

TEST_F(CaseH5Test, EmptyCaseRoundTrips) {
    const std::string path = file("empty.h5");
    CaseFileHeader h = makeHeader();
    h.np = 0;
    writeCaseH5(path, h, ParticleSet{}, nullptr);
    const CaseFileContents c = readCaseH5(path);
    EXPECT_EQ(c.header.np, 0u);
    EXPECT_EQ(c.particles.size(), 0u);
    EXPECT_EQ(c.particles.pos.size(), 0u);
}

TEST_F(CaseH5Test, StoredLayoutMatchesTheDocumentedFormat) {
    const std::string path = file("case.h5");
    const ParticleSet p = makeParticles(true);
    const BondNetwork b = makeBonds();
    writeCaseH5(path, makeHeader(), p, &b);
    const h5::File f = h5::File::openReadOnly(path);
    EXPECT_EQ(h5::readStringAttribute(f, "format"), "seaspring-case");
    EXPECT_EQ(h5::readInt64Attribute(f, "format_version"), 1);
    EXPECT_EQ(h5::readInt64Attribute(f, "np"), 6);
    EXPECT_EQ(h5::readDoubleAttribute(f, "dp"), 0.01);
    const h5::Location g = f.openGroup("particles");
    const h5::DatasetShape pos = h5::datasetShape(g, "pos");
    EXPECT_EQ(pos.rank, 2);
    EXPECT_EQ(pos.rows, 6u);
    EXPECT_EQ(pos.cols, 3u);
    EXPECT_EQ(h5::datasetShape(g, "rhop").rank, 1);
    std::vector<double> xyz(18);
    h5::readDatasetInto(g, "pos", xyz.data(), 6, 3);
    EXPECT_EQ(xyz[3 * 4 + 0], 0.1 * 4);  // row 4, x
    std::vector<float> wrong(18);
    EXPECT_HAS(errorOf([&] { h5::readDatasetInto(g, "pos", wrong.data(), 6, 3); }),
               "dataset /particles/pos: has element type float64, expected float32");
    const h5::Location bonds = f.openGroup("bonds");
    EXPECT_EQ(h5::readInt64Attribute(bonds, "first_solid"), 2);
    EXPECT_EQ(h5::readDataset<std::uint8_t>(bonds, "kind"), (std::vector<std::uint8_t>{0, 2, 3, 0}));
    EXPECT_HAS(errorOf([&] { h5::readStringAttribute(f, "dp"); }),
               "attribute 'dp' of /: has type float64, expected a string");
}

TEST_F(CaseH5Test, ChunkedAndCompressedDatasetsRoundTrip) {
    const std::string path = file("chunks.h5");
    std::vector<double> rows(10 * 3);
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = 0.5 * static_cast<double>(i) - 3.0;
    {
        h5::File f = h5::File::create(path);
        h5::writeDataset(f, "chunked", rows.data(), 10, 3, h5::WriteOptions{4, 0});
        h5::writeDataset(f, "gzip", rows.data(), 10, 3, h5::WriteOptions{4, 6});
        h5::writeStringAttribute(f, "empty", "");
        f.close();
    }
    const h5::File f = h5::File::openReadOnly(path);
    for (const char* name : {"chunked", "gzip"}) {
        std::vector<double> back(30, 99.0);
        h5::readDatasetInto(f, name, back.data(), 10, 3);
        EXPECT_TRUE(sameBytes(back, rows)) << name;
    }
    EXPECT_EQ(h5::readStringAttribute(f, "empty"), "");
    std::vector<double> back(30);
    EXPECT_HAS(errorOf([&] { h5::readDatasetInto(f, "chunked", back.data(), 9, 3); }),
               path + ": dataset /chunked: has shape [10 x 3], expected [9 x 3]");
}

// ---- Reading bad files ----------------------------------------------------------------------

TEST_F(CaseH5Test, MissingFileIsReported) {
    const std::string path = file("nope.h5");
    const std::string msg = errorOf([&] { readCaseH5(path); });
    EXPECT_HAS(msg, path + ": cannot open file: No such file or directory");
}

TEST_F(CaseH5Test, NonHdf5FileIsReported) {
    const std::string path = file("text.h5");
    std::ofstream(path) << "not hdf5\n";
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }), path + ": is not an HDF5 file");
}

TEST_F(CaseH5Test, WrongFormatAttributeIsReported) {
    const std::string path =
        damagedFile([](h5::File& f) { h5::writeStringAttribute(f, "format", "dualsphysics-bi4"); });
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }),
               path + ": attribute 'format' of /: is 'dualsphysics-bi4', expected 'seaspring-case'");
}

TEST_F(CaseH5Test, WrongFormatVersionIsReported) {
    const std::string path =
        damagedFile([](h5::File& f) { h5::writeInt64Attribute(f, "format_version", 2); });
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }),
               path + ": attribute 'format_version' of /: is 2, this build reads version 1");
}

TEST_F(CaseH5Test, MissingAttributeIsReported) {
    const std::string path = file("noattr.h5");
    h5::File::create(path).close();
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }), path + ": attribute 'format' of /: is missing");
}

TEST_F(CaseH5Test, ArrayShorterThanNpIsReported) {
    const std::string path = damagedFile([](h5::File& f) {
        const h5::Location g = f.openGroup("particles");
        g.removeChild("rhop");
        h5::writeDataset(g, "rhop", std::vector<float>(5, 1000.0f));
    });
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }),
               path + ": dataset /particles/rhop: has shape [5], expected [6]");
}

TEST_F(CaseH5Test, NpDisagreeingWithArraysIsReported) {
    const std::string path = damagedFile([](h5::File& f) { h5::writeInt64Attribute(f, "np", 7); });
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }), path + ": dataset /particles/id: has 6 rows but attribute 'np' of / is 7");
}

TEST_F(CaseH5Test, MissingDatasetAndWrongElementTypeAreReported) {
    const std::string no_mass = damagedFile([](h5::File& f) { f.openGroup("particles").removeChild("mass"); });
    EXPECT_HAS(errorOf([&] { readCaseH5(no_mass); }), no_mass + ": dataset /particles/mass: is missing");
    const std::string wide_mk = damagedFile([](h5::File& f) {
        const h5::Location g = f.openGroup("particles");
        g.removeChild("mk");
        h5::writeDataset(g, "mk", std::vector<std::uint32_t>(6, 1));
    });
    EXPECT_HAS(errorOf([&] { readCaseH5(wide_mk); }),
               wide_mk + ": dataset /particles/mk: has element type uint32, expected uint16");
}

TEST_F(CaseH5Test, InvalidParticleTypeIsReported) {
    const std::string path = damagedFile([](h5::File& f) {
        const h5::Location g = f.openGroup("particles");
        g.removeChild("type");
        h5::writeDataset(g, "type", std::vector<std::uint8_t>{0, 0, 2, 2, 3, 7});
    });
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }), path + ": /particles/type[5] = 7 is not a particle type (0..3)");
}

/// Replaces /bonds/NAME by `values`.
template <typename T>
std::function<void(h5::File&)> replaceBondArray(const std::string& name, std::vector<T> values) {
    return [name, values](h5::File& f) {
        const h5::Location g = f.openGroup("bonds");
        g.removeChild(name);
        h5::writeDataset(g, name, values);
    };
}

TEST_F(CaseH5Test, DecreasingOffsetsAreReported) {
    const std::string path = damagedFile(replaceBondArray<std::uint32_t>("offset", {0, 5, 4}));
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }),
               path + ": /bonds/offset[2] = 4 is less than /bonds/offset[1] = 5 (offsets must not decrease)");
}

TEST_F(CaseH5Test, LastOffsetNotSlotCountIsReported) {
    const std::string path = damagedFile(replaceBondArray<std::uint32_t>("offset", {0, 3, 3}));
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }),
               path + ": /bonds/offset[2] = 3, expected the slot count 4 (length of /bonds/neighbour)");
}

TEST_F(CaseH5Test, NeighbourOutOfRangeIsReported) {
    const std::string path = damagedFile(replaceBondArray<std::uint32_t>("neighbour", {3, 0, 1, 6}));
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }), path + ": /bonds/neighbour[3] = 6 is not a particle id (np = 6)");
}

TEST_F(CaseH5Test, BondArraysOfDifferentLengthAreReported) {
    const std::string path = damagedFile(replaceBondArray<double>("rest_length", {0.01, 0.01, 0.01}));
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }),
               path + ": dataset /bonds/rest_length: has shape [3], expected [4]");
}

TEST_F(CaseH5Test, BondRowsOnNonSolidParticlesAreReported) {
    const std::string path = damagedFile([](h5::File& f) {
        h5::writeInt64Attribute(f.openGroup("bonds"), "first_solid", 3);
    });
    EXPECT_HAS(errorOf([&] { readCaseH5(path); }),
               path + ": /bonds row 1 belongs to particle 4 of type fluid, expected solid (first_solid = 3)");
}

// ---- Writing bad input ----------------------------------------------------------------------

TEST_F(CaseH5Test, WrongNpInHeaderIsRejectedBeforeAnyFileIsMade) {
    const std::string path = file("case.h5");
    CaseFileHeader h = makeHeader();
    h.np = 7;
    EXPECT_HAS(errorOf([&] { writeCaseH5(path, h, makeParticles(false), nullptr); }),
               path + ": cannot write case file: np = 7 but /particles/id has 6 entries");
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(CaseH5Test, SolidsWithoutBondsAreRejected) {
    const std::string path = file("case.h5");
    EXPECT_HAS(errorOf([&] { writeCaseH5(path, makeHeader(), makeParticles(true), nullptr); }),
               path + ": cannot write case file: 2 particles are of type solid but there is no /bonds group");
}

TEST_F(CaseH5Test, FailedWriteLeavesExistingFileUntouched) {
    const std::string path = file("case.h5");
    const ParticleSet good = makeParticles(false);
    writeCaseH5(path, makeHeader(), good, nullptr);
    ParticleSet bad = makeParticles(false);
    bad.rhop.pop_back();
    EXPECT_HAS(errorOf([&] { writeCaseH5(path, makeHeader(), bad, nullptr); }),
               path + ": cannot write case file: /particles/rhop has 5 entries, expected np = 6");
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    expectSameParticles(readCaseH5(path).particles, good);
}

TEST_F(CaseH5Test, UnwritableDirectoryIsReportedAndLeavesNothing) {
    const std::string path = file("missing_dir/case.h5");
    EXPECT_HAS(errorOf([&] { writeCaseH5(path, makeHeader(), makeParticles(false), nullptr); }),
               path + ".tmp: cannot create HDF5 file");
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}

}  // namespace
}  // namespace seaspring::io
