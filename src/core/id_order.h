// SeaSpring — MIT licence.
/// \file id_order.h
/// \brief A field downloaded in sorted (cell) order put into id order on the host: out[ids[i]] =
///        sorted[i], element by element, spread over `threads` OpenMP threads (each output
///        element is written once: the result does not depend on the threads).
#pragma once

#include <cstddef>
#include <cstdint>

namespace seaspring {

/// out[ids[i]] = sorted[i] for i < n, elements of `elem_bytes` bytes; `ids` a permutation of
/// [0, n). `threads` >= 1: the run's own (a CPU run's -threads; 1 beside a GPU), never more, so
/// that processes sharing the cores are not oversubscribed.
void scatterToIdOrder(const void* sorted, std::size_t elem_bytes, const std::uint32_t* ids, std::size_t n, void* out,
                      int threads);

}  // namespace seaspring
