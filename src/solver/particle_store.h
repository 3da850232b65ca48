// SeaSpring — MIT licence.
/// \file particle_store.h
/// \brief The per-particle arrays of a backend, one per row of the field table
///        (physics/particle_fields.h), in `Buf` containers (buffers.h), sorted order.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "core/id_order.h"
#include "physics/particle_fields.h"
#include "physics/particle_updates.h"
#include "solver/buffers.h"

namespace seaspring::solver {

template <template <typename> class Buf>
struct ParticleStore {
#define SEASPRING_STORE_MEMBER(name, type, need, flags) Buf<type> name;
    SEASPRING_PARTICLE_FIELDS(SEASPRING_STORE_MEMBER)
#undef SEASPRING_STORE_MEMBER

    /// Calls f(buffer, flags, need) for every field, in table order.
    template <class F>
    void forEachField(F&& f) {
        using namespace ::seaspring::physics;
#define SEASPRING_STORE_VISIT(name, type, need, flags) f(name, unsigned(flags), FieldNeed::need);
        SEASPRING_PARTICLE_FIELDS(SEASPRING_STORE_VISIT)
#undef SEASPRING_STORE_VISIT
    }

    /// Calls f(name, buffer, flags) for every field, in table order.
    template <class F>
    void forEachNamedField(F&& f) {
        using namespace ::seaspring::physics;
#define SEASPRING_STORE_NAMED(name, type, need, flags) f(#name, name, unsigned(flags));
        SEASPRING_PARTICLE_FIELDS(SEASPRING_STORE_NAMED)
#undef SEASPRING_STORE_NAMED
    }

    /// Pointers to the arrays (null for a field this run does not allocate).
    physics::ParticleView view() {
        physics::ParticleView v;
#define SEASPRING_STORE_VIEW(name, type, need, flags) v.name = name.empty() ? nullptr : name.data();
        SEASPRING_PARTICLE_FIELDS(SEASPRING_STORE_VIEW)
#undef SEASPRING_STORE_VIEW
        return v;
    }
};

/// Particle arrays copied to the host in id order: the fields flagged physics::kHost (the
/// others stay empty), one member per row of the field table.
struct HostParticles {
#define SEASPRING_HOST_MEMBER(name, type, need, flags) std::vector<type> name;
    SEASPRING_PARTICLE_FIELDS(SEASPRING_HOST_MEMBER)
#undef SEASPRING_HOST_MEMBER

    /// Calls f(vector, flags) for every field, in table order.
    template <class F>
    void forEachField(F&& f) {
        using namespace ::seaspring::physics;
#define SEASPRING_HOST_VISIT(name, type, need, flags) f(name, unsigned(flags));
        SEASPRING_PARTICLE_FIELDS(SEASPRING_HOST_VISIT)
#undef SEASPRING_HOST_VISIT
    }
    template <class F>
    void forEachField(F&& f) const {
        using namespace ::seaspring::physics;
#define SEASPRING_HOST_VISIT(name, type, need, flags) f(name, unsigned(flags));
        SEASPRING_PARTICLE_FIELDS(SEASPRING_HOST_VISIT)
#undef SEASPRING_HOST_VISIT
    }
};

}  // namespace seaspring::solver

namespace seaspring::solver {

/// Calls f(store_buffer, host_vector, flags) for every field, in table order.
template <template <typename> class Buf, class F>
void forEachFieldPair(ParticleStore<Buf>& s, HostParticles& h, F&& f) {
    using namespace ::seaspring::physics;
#define SEASPRING_PAIR_VISIT(name, type, need, flags) f(s.name, h.name, unsigned(flags));
    SEASPRING_PARTICLE_FIELDS(SEASPRING_PAIR_VISIT)
#undef SEASPRING_PAIR_VISIT
}

/// The fields of `s` with a flag in `any` (every field for ~0u) and none in `none`, copied to
/// `out` in id order (the work of the device, if any, finished). Each field goes through one
/// staging buffer the caller keeps (`stage`; `ids` takes the sorted ids), so a download every
/// -blowupcheck steps allocates nothing and touches no fresh pages, and `out`'s vectors keep
/// their capacity when the caller reuses it. The reordering runs on `threads` host threads
/// (scatterToIdOrder: the same result on any number).
template <template <typename> class Buf>
void downloadInIdOrder(ParticleStore<Buf>& s, std::vector<std::uint32_t>& ids, std::vector<unsigned char>& stage,
                       HostParticles& out, unsigned any, unsigned none, int threads) {
    copyToHost(s.id, ids);
    const std::uint32_t* id = ids.data();
    forEachFieldPair(s, out, [&](auto& buf, auto& host, unsigned flags) {
        if ((any != ~0u && (flags & any) == 0) || (flags & none) != 0 || buf.empty()) return;
        using T = typename std::remove_reference_t<decltype(host)>::value_type;
        const std::size_t n = buf.size();
        if (stage.size() < n * sizeof(T)) stage.resize(n * sizeof(T));
        copyToHostBytes(buf, stage.data());
        host.resize(n);
        scatterToIdOrder(stage.data(), reinterpret_cast<unsigned char*>(host.data()), sizeof(T), id, n, threads);
    });
}

}  // namespace seaspring::solver
