// SeaSpring — MIT licence.
/// \file sorted_block.h
/// \brief A block of particles of a part file (the active fluid, the boundary particles) as the
///        solver's divide holds it: sorted by (cell, id) (physics::sortKey) on a cell grid, with
///        its PosCell (physics::makePosCell), (velocity, density) and the per-cell start
///        indices that the physics' neighbour loops (physics::forEachCandidateRow) read.
///        The post-processing subcommands rebuild the solver's sorted state with it and call
///        the solver's own physics functions on it.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "io/part_output.h"
#include "physics/cell_grid.h"
#include "physics/sph_types.h"

namespace seaspring::post {

/// Sorted arrays of one or more blocks, laid one after the other (as the solver's boundary
/// block [0, nbound) and fluid block after it).
struct SortedParticles {
    std::vector<physics::Float4> poscell;  ///< PosCell of each sorted slot
    std::vector<physics::Float4> velrho;   ///< (vx, vy, vz, rhop) of each sorted slot
    std::vector<std::uint32_t> index;      ///< the part-file index (= particle id) of each slot
};

/// Appends the part-file particles `members` sorted by (cell, id) on grid `g` to `s`, and
/// returns the block's cell starts (cellCount() + 1 entries, absolute slot indices into `s`).
/// In 2D (`dim` 2) every position's y is replaced by `y2d` unless it is NaN. Positions outside
/// the grid are clamped to its edge cells (makePosCell): callers check that the grid holds them.
std::vector<std::uint32_t> appendSortedBlock(const io::PartData& d, const std::vector<std::uint32_t>& members,
                                             const physics::CellGrid& g, int dim, SortedParticles& s,
                                             double y2d = std::nan(""));

}  // namespace seaspring::post
