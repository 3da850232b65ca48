// SeaSpring — MIT licence.
/// \file test_part_writer.cpp
/// \brief The part writer (files written in the background equal the immediate ones, its spare
///        arrays, its errors) and the state's copy into id order on several threads.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/id_order.h"
#include "error_expect.h"
#include "io/part_output.h"
#include "io/part_writer.h"
#include "part_test_util.h"

namespace seaspring::io {
namespace {

namespace fs = std::filesystem;
using test::errorOf;
using test::Particles;
using test::Scratch;
using test::makeParticles;
using test::sameBytes;

/// The particles of makeParticles as a part writer's arrays (ids, MKs and masses borrowed).
PartArrays arraysOf(const Particles& p, int index, double time) {
    PartArrays a;
    a.index = index;
    a.time = time;
    a.step = index;
    a.np = p.id.size();
    a.pos = p.pos;
    a.vel = p.vel;
    a.rhop = p.rhop;
    a.press = p.press;
    a.type = p.type;
    a.excluded = p.excluded;
    a.id = p.id.data();
    a.mk = p.mk.data();
    a.mass = p.mass.data();
    a.constants = p.constants;
    return a;
}

}  // namespace

// The part writer, in the background and at once: the same files, in order, byte for byte.
TEST(PartWriter, BackgroundFilesEqualTheImmediateOnes) {
    const Scratch scratch;
    const Particles p = makeParticles();
    for (bool background : {false, true}) {
        const std::string out = (fs::path(scratch.dir) / (background ? "bg" : "now")).string();
        PartWriter w(out, background);
        for (int k = 0; k < 4; ++k) {
            PartArrays a = arraysOf(p, k, 0.1 * k);  // ids, MKs, masses borrowed from p
            a.rhop[0] = 1000.f + float(k);             // each output its own values
            EXPECT_EQ(w.submit(std::move(a)), partFileName(k));
        }
        w.wait();
        for (int k = 0; k < 4; ++k) {
            const PartData d = readPartH5((fs::path(out) / partFileName(k)).string());
            EXPECT_EQ(d.rhop[0], 1000.f + float(k)) << (background ? "background" : "at once") << ", file " << k;
            EXPECT_EQ(d.step, k);
            EXPECT_TRUE(sameBytes(d.pos, p.pos));
            EXPECT_EQ(d.mk, p.mk);
            EXPECT_TRUE(sameBytes(d.mass, p.mass));
        }
    }
}

// The next output refills the last file's arrays (no fresh pages): takeSpare gives them back
// once written, with their values and sizes, and then nothing until the next submit.
TEST(PartWriter, TheSpareArraysAreTheLastFilesOnceWritten) {
    const Scratch scratch;
    const Particles p = makeParticles();
    for (bool background : {false, true}) {
        PartWriter w((fs::path(scratch.dir) / (background ? "bg" : "now")).string(), background);
        EXPECT_TRUE(w.takeSpare().pos.empty());
        PartArrays a = arraysOf(p, 0, 0.0);
        a.rhop[0] = 1234.f;
        const std::vector<double> pos = a.pos;
        w.submit(std::move(a));
        PartArrays s = w.takeSpare();
        EXPECT_EQ(s.rhop.size(), p.id.size());
        EXPECT_EQ(s.rhop[0], 1234.f);
        EXPECT_TRUE(sameBytes(s.pos, pos));
        EXPECT_TRUE(w.takeSpare().pos.empty());
        const PartData d = readPartH5((fs::path(scratch.dir) / (background ? "bg" : "now") / partFileName(0)).string());
        EXPECT_EQ(d.rhop[0], 1234.f);  // written before it was handed back
    }
}

// A write that fails in the background is not lost: its error comes out of the next submit or
// of wait(), naming the file.
TEST(PartWriter, ABackgroundErrorIsThrownByTheNextCall) {
    const Scratch scratch;
    const Particles p = makeParticles();
    const std::string out = (fs::path(scratch.dir) / "run").string();
    fs::create_directories(fs::path(out) / "data/part_0000.h5.tmp");  // blocks file 0
    {
        PartWriter w(out, true);
        w.submit(arraysOf(p, 0, 0.0));
        const std::string msg = errorOf([&] { w.wait(); });
        EXPECT_HAS(msg, "data/part_0000.h5.tmp: cannot create the part file");
        w.wait();  // reported once
    }
    fs::create_directories(fs::path(out) / "data/part_0000.h5.tmp");  // the failed write removed it
    {
        PartWriter w(out, true);
        w.submit(arraysOf(p, 0, 0.0));
        const std::string msg = errorOf([&] { w.submit(arraysOf(p, 1, 0.1)); });
        EXPECT_HAS(msg, "data/part_0000.h5.tmp: cannot create the part file");
    }
}

// The state into id order on several threads (core/id_order.h): every element size the
// particle fields have (and one they do not), one and three threads, against the plain loop.
TEST(IdOrder, ScatterEqualsThePlainLoopOnAnyThreads) {
    const std::size_t n = 1003;
    std::vector<std::uint32_t> id(n);
    for (std::size_t i = 0; i < n; ++i) id[i] = std::uint32_t((i * 389u + 17u) % n);  // 389 is prime to 1003
    for (std::size_t elem : {1u, 4u, 12u, 16u, 24u, 40u}) {
        std::vector<unsigned char> src(n * elem), want(n * elem);
        for (std::size_t k = 0; k < src.size(); ++k) src[k] = static_cast<unsigned char>(k * 131u + elem);
        for (std::size_t i = 0; i < n; ++i) std::memcpy(&want[id[i] * elem], &src[i * elem], elem);
        for (int threads : {1, 3}) {
            std::vector<unsigned char> got(n * elem, 0);
            scatterToIdOrder(src.data(), got.data(), elem, id.data(), n, threads);
            EXPECT_EQ(got, want) << elem << " bytes, " << threads << " threads";
        }
    }
    std::vector<unsigned char> one(1);
    EXPECT_THROW(scatterToIdOrder(one.data(), one.data(), 0, id.data(), 0, 1), std::invalid_argument);
}

}  // namespace seaspring::io
