// SeaSpring — MIT licence.
/// \file solver_case_test_util.h
/// \brief What the loadSolverCase tests share (test_solver_case.cpp, test_solver_case_errors.cpp):
///        cases generated in-process by gencase, and copies of their resolved XML edited in one
///        place, with the error that loading them gives.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>

#include "core/error.h"
#include "gencase_test_util.h"
#include "io/case_h5.h"
#include "solver/solver_case.h"

namespace seaspring::test::solver_case {

using solver::loadSolverCase;

using test::kPool;  // gencase_test_util.h

// The pool plus a moving wall (mkbound 1, x = -0.1: 25), a VCPM beam (mkbound 2: 3*2*2 = 12)
// clamped to a block (mkbound 3: 2*2*2 = 8).
inline const char* kMovingAndSolid =
    "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"-0.1\" y=\"0\" z=\"0\"/>"
    "<size x=\"0\" y=\"0.4\" z=\"0.4\"/></drawbox>\n"
    "<setmkbound mk=\"2\"/><drawbox><boxfill>solid</boxfill><point x=\"0.6\" y=\"0\" z=\"0\"/>"
    "<size x=\"0.2\" y=\"0.1\" z=\"0.1\"/></drawbox>\n"
    "<setmkbound mk=\"3\"/><drawbox><boxfill>solid</boxfill><point x=\"0.9\" y=\"0\" z=\"0\"/>"
    "<size x=\"0.1\" y=\"0.1\" z=\"0.1\"/></drawbox>";
inline const char* kMotion =
    "<motion><objreal ref=\"1\"><begin mov=\"1\" start=\"0\"/><mvrect id=\"1\" duration=\"1\">"
    "<vel x=\"0.1\" y=\"0\" z=\"0\"/></mvrect></objreal></motion>";
inline const char* kSolid =
    "<vcpmsolids><solid mkbound=\"2\" mkclamp=\"3\" density=\"2500\" youngmod=\"3e6\" "
    "poissratio=\"0.3\"/></vcpmsolids>\n<gauges><default><output value=\"true\"/></default>"
    "<velocity name=\"V\"><point x=\"#1/4\" y=\"0\" z=\"0\"/></velocity></gauges>";

inline std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A case generated in-process: OUT/Case.xml and OUT/Case.h5.
struct Generated {
    std::string dir, base, xml;  ///< scratch dir, OUTDIR/NAME, text of NAME.xml
    gencase::GeneratedCase g;    ///< what gencase generated
};

inline Generated generate(const std::string& tag, const std::string& mainlist,
                   const std::string& casedef_extra = "", const std::string& special = "",
                   const std::string& parameters = "", bool two_d = false) {
    Generated r;
    r.dir = test::scratchDir("solver_case_" + tag);
    const std::string def =
        test::writeFile(r.dir, "Case_Def.xml",
                        test::caseXml(mainlist, 0.1, two_d, casedef_extra, special, parameters));
    std::ostringstream log;
    auto b = test::buildCaseKeepBuilder(def, log);
    b->write();
    r.g = b->result();
    r.base = r.dir + "/out/Case";
    r.xml = readText(r.base + ".xml");
    return r;
}

inline const Generated& pool() {
    static const Generated p = generate("pool", kPool);
    return p;
}

/// The resolved XML with the first `from` after `after` replaced by `to`, written next to the
/// original as NAME.xml (so that it names the same Case.h5), and the message of loading it
/// ("" when it loads). `after` = "<execution>" skips the copy of the definition in <casedef>.
struct Edited {
    std::string path, text, error, after;
    /// "PATH:LINE" of the first line after `after` holding `needle`.
    std::string where(const std::string& needle) const {
        const std::size_t from = text.find(after);
        const std::size_t at = text.find(needle, from == std::string::npos ? 0 : from);
        EXPECT_NE(at, std::string::npos) << "'" << needle << "' is not in the edited case";
        if (at == std::string::npos) return path + ":?";
        return path + ":" +
               std::to_string(1 +
                              std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
    }
    /// "PATH:LINE:" as in errors thrown for the XML.
    std::string at(const std::string& needle) const { return where(needle) + ":"; }
};

inline Edited edit(const Generated& c, const std::string& from, const std::string& to,
            const std::string& after = "<execution>") {
    Edited e;
    e.text = c.xml;
    e.after = after;
    const std::size_t start = e.text.find(after);
    EXPECT_NE(start, std::string::npos) << "'" << after << "' is not in the resolved case";
    const std::size_t at = e.text.find(from, start == std::string::npos ? 0 : start);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the resolved case";
    if (at != std::string::npos) e.text.replace(at, from.size(), to);
    e.path = test::writeFile(c.dir + "/out", "Edited.xml", e.text);
    try {
        loadSolverCase(e.path);
    } catch (const Error& err) {
        e.error = err.what();
    }
    return e;
}

inline void expectContains(const std::string& text, const std::string& what) {
    EXPECT_NE(text.find(what), std::string::npos) << "expected '" << what << "' in:\n" << text;
}

/// Replaces the value of parameter `key` and expects "PATH:LINE: <parameter> key=".." value="..":
/// ... with each of `parts` in the message.
inline void expectParameterError(const std::string& key, const std::string& old_value,
                          const std::string& value, std::initializer_list<const char*> parts) {
    SCOPED_TRACE(key + "=" + value);
    const std::string from = "key=\"" + key + "\" value=\"" + old_value + "\"";
    const Edited e = edit(pool(), from, "key=\"" + key + "\" value=\"" + value + "\"");
    ASSERT_FALSE(e.error.empty()) << "loaded despite " << key << "=" << value;
    expectContains(e.error, e.at("key=\"" + key + "\"") + " <parameter> key=\"" + key +
                                "\" value=\"" + value + "\"");
    for (const char* p : parts) expectContains(e.error, p);
}


}  // namespace seaspring::test::solver_case
