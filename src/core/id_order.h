// SeaSpring — MIT licence.
/// \file id_order.h
/// \brief A field downloaded in sorted (cell) order put into id order on the host: out[ids[i]] =
///        sorted[i], element by element, spread over the host's OpenMP threads (each output
///        element is written once: the result does not depend on the threads).
#pragma once

#include <cstddef>
#include <cstdint>

namespace seaspring {

/// out[ids[i]] = sorted[i] for i < n, elements of `elem_bytes` bytes; `ids` a permutation of
/// [0, n).
void scatterToIdOrder(const void* sorted, std::size_t elem_bytes, const std::uint32_t* ids, std::size_t n, void* out);

}  // namespace seaspring
