// SeaSpring — MIT licence.
/// \file host_device.h
/// \brief SEASPRING_HD marks functions compiled for host and device alike.
#pragma once

#if defined(__CUDACC__)
#define SEASPRING_HD __host__ __device__
#else
#define SEASPRING_HD
#endif
