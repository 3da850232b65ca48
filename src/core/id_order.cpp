// SeaSpring — MIT licence.
#include "core/id_order.h"

#include <cstring>

namespace seaspring {

namespace {

template <std::size_t kBytes>
void scatterFixed(const unsigned char* s, const std::uint32_t* ids, std::int64_t n, unsigned char* o) {
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) std::memcpy(o + std::size_t(ids[i]) * kBytes, s + std::size_t(i) * kBytes, kBytes);
}

}  // namespace

void scatterToIdOrder(const void* sorted, std::size_t elem_bytes, const std::uint32_t* ids, std::size_t n, void* out) {
    const auto* s = static_cast<const unsigned char*>(sorted);
    auto* o = static_cast<unsigned char*>(out);
    const auto m = static_cast<std::int64_t>(n);
    switch (elem_bytes) {  // the particle fields' sizes: a fixed-size copy each
        case 1: return scatterFixed<1>(s, ids, m, o);
        case 2: return scatterFixed<2>(s, ids, m, o);
        case 4: return scatterFixed<4>(s, ids, m, o);
        case 8: return scatterFixed<8>(s, ids, m, o);
        case 16: return scatterFixed<16>(s, ids, m, o);
        case 24: return scatterFixed<24>(s, ids, m, o);
        default: break;
    }
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < m; ++i) std::memcpy(o + std::size_t(ids[i]) * elem_bytes, s + std::size_t(i) * elem_bytes, elem_bytes);
}

}  // namespace seaspring
