// SeaSpring — MIT licence.
/// \file mk_blocks.h
/// \brief The particle blocks of a case: each MK's particles are one contiguous id range, in
///        the order fixed, moving, solid, fluid (`<particles>` of the resolved case).
#pragma once

#include <cstdint>
#include <vector>

#include <pugixml.hpp>

#include "case/xml_source.h"
#include "core/particle_set.h"

namespace seaspring::model {

/// One `<fixed|moving|solid|fluid mk=.. mkbound|mkfluid=.. begin=.. count=..>` block: the
/// particles of one MK, a contiguous id range.
struct MkBlock {
    ParticleType type = ParticleType::Fixed;
    int mk = 0;        ///< global MK
    int mk_local = 0;  ///< mkbound (boundaries, solids) or mkfluid (fluid), as written in the case
    std::uint32_t begin = 0, count = 0;
};

/// `<particles>`: the blocks in id order and the particle counts by type.
struct ParticleBlocks {
    std::vector<MkBlock> blocks;
    std::uint32_t np = 0, nfixed = 0, nmoving = 0, nsolid = 0, nfluid = 0;
};

/// Appends `<particles np nfixed nmoving nsolid nfluid mkboundfirst mkfluidfirst>` with one
/// child per block to `parent`. `mkboundfirst` is the global MK of mkbound 0.
void writeParticleBlocks(pugi::xml_node parent, const std::vector<MkBlock>& blocks, int mkboundfirst);

/// Reads `<particles>` and checks that the blocks follow each other from id 0, in type order,
/// one per MK, and add up to the counts. `nodes` (may be null) receives the block elements,
/// in the same order, for later messages.
ParticleBlocks readParticleBlocks(const XmlSource& src, pugi::xml_node parts,
                                  std::vector<pugi::xml_node>* nodes);

}  // namespace seaspring::model
