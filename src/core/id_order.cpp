// SeaSpring — MIT licence.
#include "core/id_order.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace seaspring {

namespace {

/// The loop with the element size a constant (each memcpy one or two moves).
template <std::size_t kElem>
void scatter(const unsigned char* src, unsigned char* dst, const std::uint32_t* id, std::size_t n, int threads) {
    const long long nn = static_cast<long long>(n);
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
    for (long long i = 0; i < nn; ++i) std::memcpy(dst + std::size_t(id[i]) * kElem, src + std::size_t(i) * kElem, kElem);
}

}  // namespace

void scatterToIdOrder(const unsigned char* src, unsigned char* dst, std::size_t elem, const std::uint32_t* id,
                      std::size_t n, int threads) {
    if (threads < 1) threads = 1;
    switch (elem) {
        case 1: return scatter<1>(src, dst, id, n, threads);
        case 2: return scatter<2>(src, dst, id, n, threads);
        case 4: return scatter<4>(src, dst, id, n, threads);
        case 8: return scatter<8>(src, dst, id, n, threads);
        case 12: return scatter<12>(src, dst, id, n, threads);
        case 16: return scatter<16>(src, dst, id, n, threads);
        case 24: return scatter<24>(src, dst, id, n, threads);
        case 32: return scatter<32>(src, dst, id, n, threads);
        default: break;
    }
    if (elem == 0 || elem > 64) throw std::invalid_argument("scatterToIdOrder: element of " + std::to_string(elem) + " bytes");
    const long long nn = static_cast<long long>(n);
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
    for (long long i = 0; i < nn; ++i) std::memcpy(dst + std::size_t(id[i]) * elem, src + std::size_t(i) * elem, elem);
}

}  // namespace seaspring
