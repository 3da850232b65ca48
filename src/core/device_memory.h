// SeaSpring — MIT licence.
/// \file device_memory.h
/// \brief Every device allocation of the solver goes through deviceAllocate / deviceFree: they
///        keep the bytes held now and at most (the run's summary and run.json say them), and an
///        allocation that does not fit stops the run with outOfDeviceMemoryMessage
///        (memory_budget.h): what it asked for, what the solver held, what the device had free and
///        what to change, instead of cudaMalloc's bare "out of memory". Implemented in
///        cuda/device_memory.cu, and in cpu/device_memory_none.cpp for a build without CUDA
///        (whose deviceAllocate throws).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/error.h"

namespace seaspring {

/// An allocation that did not fit the device (its message: outOfDeviceMemoryMessage).
class OutOfDeviceMemory : public Error {
public:
    using Error::Error;
};

/// cudaMalloc of `bytes` into *p (bytes > 0). Throws OutOfDeviceMemory when it does not fit,
/// seaspring::Error on another failure. SEASPRING_DEVICE_MEMORY_LIMIT (bytes) in the environment
/// caps what the process's allocations may hold (a GPU shared with other work; tests): beyond it
/// an allocation fails as if the device were that large.
void deviceAllocate(void** p, std::size_t bytes);
/// cudaFree of p (null: nothing), which deviceAllocate gave with `bytes`.
void deviceFree(void* p, std::size_t bytes);

/// Bytes the process's allocations through deviceAllocate hold now, and the most they held since
/// the process began or the last resetDevicePeak.
std::uint64_t deviceBytesHeld();
std::uint64_t deviceBytesPeak();
/// The peak becomes the bytes held now (a new backend: its run's peak is its own).
void resetDevicePeak();

}  // namespace seaspring
