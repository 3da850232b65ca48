// SeaSpring — MIT licence.
/// \file part_writer.cpp
/// \brief PartWriter: part files written on a background thread, one at a time.
#include "io/part_writer.h"

#include <memory>
#include <utility>

namespace seaspring::io {

PartFrame frameOf(const PartArrays& a) {
    PartFrame f;
    f.index = a.index;
    f.time = a.time;
    f.step = a.step;
    f.np = a.np;
    f.pos = a.pos.data();
    f.vel = a.vel.data();
    f.rhop = a.rhop.data();
    f.press = a.press.data();
    f.id = a.id;
    f.type = a.type.data();
    f.mk = a.mk;
    f.excluded = a.excluded.data();
    f.mass = a.mass;
    f.constants = a.constants;
    if (!a.disp.empty()) {
        f.disp = a.disp.data();
        f.strain = a.strain.data();
        f.broken = a.broken.data();
        f.damage = a.damage.data();
    }
    return f;
}

PartWriter::PartWriter(std::string outdir, bool background) : outdir_(std::move(outdir)), background_(background) {}

PartWriter::~PartWriter() {
    if (pending_.valid()) pending_.wait();
}

std::string PartWriter::submit(PartArrays a) {
    wait();
    const std::string rel = partFileName(a.index);
    last_ = std::make_shared<PartArrays>(std::move(a));
    if (!background_) {
        writePartH5(outdir_, frameOf(*last_));
        return rel;
    }
    pending_ = std::async(std::launch::async, [dir = outdir_, job = last_] { writePartH5(dir, frameOf(*job)); });
    return rel;
}

PartArrays PartWriter::takeSpare() {
    wait();
    PartArrays spare;
    if (last_) spare = std::move(*last_);
    last_.reset();
    return spare;
}

void PartWriter::wait() {
    if (!pending_.valid()) return;
    std::future<void> done = std::move(pending_);
    done.get();  // rethrows the write's error
}

}  // namespace seaspring::io
