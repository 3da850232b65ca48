// SeaSpring — MIT licence.
/// \file checkpoint_data.h
/// \brief The content of a restart file in memory: named arrays kept as raw bytes (the engine's
///        sorted particle fields, cell starts, solid arrays; each with its element size),
///        named numbers and named texts. Each part of the solver writes its own names under its
///        own prefix ("engine/", "loop/", "stepper/", "gauges/", ...) and reads them back;
///        io/checkpoint_h5.h stores it in HDF5. Raw bytes are exact: a restart continues with
///        the same bits, whatever backend wrote or reads them (the backends' arrays are
///        bit-identical).
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.h"

namespace seaspring {

struct CheckpointData {
    struct Blob {
        std::uint32_t elem_size = 1;
        std::vector<std::uint8_t> bytes;
    };
    std::map<std::string, Blob> blobs;
    std::map<std::string, double> reals;
    std::map<std::string, long long> ints;
    std::map<std::string, std::string> texts;
    std::string source;  ///< the file it was read from (messages)

    template <typename T>
    void putArray(const std::string& name, const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable<T>::value, "raw bytes of a trivially copyable type");
        Blob& b = blobs[name];
        b.elem_size = std::uint32_t(sizeof(T));
        b.bytes.resize(v.size() * sizeof(T));
        if (!v.empty()) std::memcpy(b.bytes.data(), v.data(), b.bytes.size());
    }
    /// The array `name`; throws naming the file when it is missing or of another element size.
    template <typename T>
    std::vector<T> getArray(const std::string& name) const {
        static_assert(std::is_trivially_copyable<T>::value, "raw bytes of a trivially copyable type");
        const auto it = blobs.find(name);
        if (it == blobs.end()) throw Error(source + ": restart file has no array '" + name + "'");
        if (it->second.elem_size != sizeof(T) || it->second.bytes.size() % sizeof(T) != 0)
            throw Error(source + ": restart array '" + name + "' has elements of " +
                        std::to_string(it->second.elem_size) + " bytes, expected " + std::to_string(sizeof(T)));
        std::vector<T> v(it->second.bytes.size() / sizeof(T));
        if (!v.empty()) std::memcpy(v.data(), it->second.bytes.data(), it->second.bytes.size());
        return v;
    }
    double real(const std::string& name) const { return find(reals, name); }
    long long integer(const std::string& name) const { return find(ints, name); }
    const std::string& text(const std::string& name) const { return find(texts, name); }
    bool has(const std::string& name) const {
        return blobs.count(name) || reals.count(name) || ints.count(name) || texts.count(name);
    }

private:
    template <class M>
    const typename M::mapped_type& find(const M& m, const std::string& name) const {
        const auto it = m.find(name);
        if (it == m.end()) throw Error(source + ": restart file has no value '" + name + "'");
        return it->second;
    }
};

}  // namespace seaspring
