// SeaSpring — MIT licence.
/// \file resolved_case_writer.h
/// \brief Writes gencase's outputs: the resolved case OUTDIR/NAME.xml (definition, derived
///        constants, parameters with defaults, particle blocks, motion, solids, domain), the
///        particles OUTDIR/NAME.h5, optionally a ParaView preview OUTDIR/NAME.vtu, and each
///        non-empty shape set X as OUTDIR/NAME_X_Actual.vtk (GenCase's name). The
///        sections of the case model are written by its writers (src/case).
#pragma once

#include <iosfwd>
#include <string>

#include <pugixml.hpp>

#include "gencase/case_builder.h"

namespace seaspring::gencase {

/// The resolved case document (what NAME.xml contains).
void buildResolvedCase(pugi::xml_document& doc, const XmlSource& src, const GeneratedCase& g,
                       const std::string& particles_file);

/// Writes every output under temporary names and renames them only once all succeeded; on
/// failure nothing is left behind.
void writeGeneratedCase(const XmlSource& src, const GeneratedCase& g, const std::string& output_base,
                        bool save_vtk, std::ostream& log);

}  // namespace seaspring::gencase
