// SeaSpring — MIT licence.
/// \file id_order.h
/// \brief Host arrays from the solver's sorted order into particle-id order, on several
///        threads: the copy every output, blow-up diagnosis and restart file makes of the state.
#pragma once

#include <cstddef>
#include <cstdint>

namespace seaspring {

/// dst[id[i]] = src[i] for i < n, elements of `elem` bytes (1 to 64). `id` is a permutation
/// of [0, n), so the result does not depend on `threads` (OpenMP threads; <= 1: one).
void scatterToIdOrder(const unsigned char* src, unsigned char* dst, std::size_t elem, const std::uint32_t* id,
                      std::size_t n, int threads);

}  // namespace seaspring
