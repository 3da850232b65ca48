// SeaSpring — MIT licence.
/// \file fuzz_solver_case.cpp
/// \brief libFuzzer target: the solver's case loading (solver::loadSolverCase, what `seaspring`
///        reads first) on any resolved case NAME.xml beside a valid NAME.h5: the particle file of
///        a small 2D dam break with a VCPM gate, made once by gencase from a definition built in
///        here. Only seaspring::Error may come out.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>

#include "core/error.h"
#include "fuzz_common.h"
#include "gencase/case_builder.h"
#include "solver/solver_case.h"

namespace {

/// A small case with fluid, a wall, a clamped VCPM gate, a motion and gauges: its NAME.h5 is
/// what every input's NAME.xml is read beside (so that the XML, not the HDF5, is fuzzed).
const char* kBaseDef = R"(<?xml version="1.0" encoding="UTF-8" ?>
<case>
  <casedef>
    <constantsdef>
      <gravity x="0" y="0" z="-9.81" />
      <rhop0 value="1000" />
      <hswl value="0" auto="true" />
      <gamma value="7" />
      <speedsystem value="0" auto="true" />
      <coefsound value="20" />
      <speedsound value="0" auto="true" />
      <coefh value="1.2" />
      <cflnumber value="0.2" />
    </constantsdef>
    <mkconfig boundcount="240" fluidcount="10" />
    <geometry>
      <definition dp="0.02">
        <pointmin x="-0.1" y="0" z="-0.1" />
        <pointmax x="1.1" y="0" z="0.7" />
      </definition>
      <commands>
        <mainlist>
          <setshapemode>actual | dp | bound</setshapemode>
          <setdrawmode mode="full" />
          <setmkfluid mk="0" />
          <drawbox>
            <boxfill>solid</boxfill>
            <point x="0" y="-1" z="0" />
            <size x="0.3" y="2" z="0.4" />
          </drawbox>
          <setmkbound mk="0" />
          <drawbox>
            <boxfill>bottom | left | right</boxfill>
            <point x="0" y="-1" z="0" />
            <size x="1" y="2" z="0.6" />
          </drawbox>
          <setmkbound mk="1" />
          <drawbox>
            <boxfill>solid</boxfill>
            <point x="0.6" y="-1" z="0.02" />
            <size x="0.04" y="2" z="0.3" />
          </drawbox>
          <shapeout file="" />
        </mainlist>
      </commands>
    </geometry>
  </casedef>
  <execution>
    <special>
      <vcpmsolids>
        <solid mkbound="1" mkclamp="0" youngmod="1e7" poissratio="0.3" density="1100" />
      </vcpmsolids>
    </special>
    <parameters>
      <parameter key="StepAlgorithm" value="2" />
      <parameter key="Kernel" value="2" />
      <parameter key="ViscoTreatment" value="1" />
      <parameter key="Visco" value="0.1" />
      <parameter key="DensityDT" value="3" />
      <parameter key="DensityDTvalue" value="0.1" />
      <parameter key="TimeMax" value="0.1" />
      <parameter key="TimeOut" value="0.01" />
    </parameters>
  </execution>
</case>
)";

std::string& basePath() {
    static std::string path;
    return path;
}

void makeBase() {
    const std::string dir = seaspring::fuzz::scratchDir();
    const std::uint8_t* d = reinterpret_cast<const std::uint8_t*>(kBaseDef);
    seaspring::gencase::GencaseOptions opt;
    opt.definition = seaspring::fuzz::writeInput("Base_Def.xml", d, std::string(kBaseDef).size());
    opt.output_base = dir + "/Base";
    std::ostringstream log;
    seaspring::gencase::CaseBuilder builder(opt, log);
    builder.build();
    builder.checkForSolver();
    builder.write();
    // Every input is read as Fuzz.xml beside a copy of the base's particles.
    std::filesystem::copy_file(dir + "/Base.h5", dir + "/Fuzz.h5", std::filesystem::copy_options::overwrite_existing);
    basePath() = dir + "/Fuzz";
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    seaspring::fuzz::limitMemory();
    makeBase();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 65536) return 0;
    if (basePath().empty()) {  // replayed without libFuzzer's initialiser
        seaspring::fuzz::limitMemory();
        makeBase();
    }
    seaspring::fuzz::writeInput("Fuzz.xml", data, size);
    try {
        (void)seaspring::solver::loadSolverCase(basePath());
    } catch (const seaspring::Error& e) {
        seaspring::fuzz::handled(e);
    }
    return 0;
}
