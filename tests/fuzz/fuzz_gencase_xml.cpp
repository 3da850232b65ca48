// SeaSpring — MIT licence.
/// \file fuzz_gencase_xml.cpp
/// \brief libFuzzer target: gencase on any case definition (the bytes are CASE_Def.xml): reading,
///        expressions, geometry, motion, solids, gauges, parameters, normals and the solver's
///        checks (CaseBuilder::build and checkForSolver, as `gencase` runs them; nothing is
///        written). Only seaspring::Error may come out; memory is bounded (fuzz_common.h).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "core/error.h"
#include "fuzz_common.h"
#include "gencase/case_builder.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    seaspring::fuzz::limitMemory();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 65536) return 0;
    seaspring::fuzz::limitMemory();  // also when replayed without libFuzzer's initialiser
    const std::string def = seaspring::fuzz::writeInput("Fuzz_Def.xml", data, size);
    seaspring::gencase::GencaseOptions opt;
    opt.definition = def;
    opt.output_base = seaspring::fuzz::scratchDir() + "/out/Fuzz";
    std::ostringstream log;
    try {
        seaspring::gencase::CaseBuilder builder(opt, log);
        builder.build();
        builder.checkForSolver();
    } catch (const seaspring::Error& e) {
        seaspring::fuzz::handled(e);
    }
    return 0;
}
