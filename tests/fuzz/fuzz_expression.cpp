// SeaSpring — MIT licence.
/// \file fuzz_expression.cpp
/// \brief libFuzzer target: gencase's expression evaluator (GenCase `#...` values) on any text,
///        with a few variables and the grid defined (roundpos). Only ExpressionError may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "fuzz_common.h"
#include "gencase/expression.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 4096) return 0;  // the XML attributes it reads are short; depth limits are tested apart
    seaspring::gencase::ExpressionEvaluator ev;
    ev.define("x", 1.5);
    ev.define("n", 3.0, true);
    ev.define("a2", -0.25);
    ev.setGrid(seaspring::Vec3d{0.0, 0.0, 0.0}, 0.01);
    try {
        (void)ev.evaluate(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const seaspring::gencase::ExpressionError& e) {
        seaspring::fuzz::handled(e);
    } catch (const seaspring::Error& e) {
        seaspring::fuzz::handled(e);
    }
    return 0;
}
