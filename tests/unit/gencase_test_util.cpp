// SeaSpring — MIT licence.
/// \file gencase_test_util.cpp
#include "gencase_test_util.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "core/error.h"

namespace seaspring::test {

namespace fs = std::filesystem;

std::string scratchDir(const std::string& tag) {
    const fs::path p = fs::temp_directory_path() /
                       ("seaspring_test_" + tag + "_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

std::string writeFile(const std::string& dir, const std::string& name, const std::string& text) {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
}

std::string caseXml(const std::string& mainlist, double dp, bool two_d, const std::string& casedef_extra,
                    const std::string& special, const std::string& parameters) {
    std::ostringstream os;
    os << "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<case>\n <casedef>\n  <constantsdef>\n"
       << "   <gravity x=\"0\" y=\"0\" z=\"-9.81\" />\n   <rhop0 value=\"1000\" />\n"
       << "   <hswl value=\"0\" auto=\"true\" />\n   <gamma value=\"7\" />\n"
       << "   <speedsystem value=\"0\" auto=\"true\" />\n   <coefsound value=\"20\" />\n"
       << "   <speedsound value=\"0\" auto=\"true\" />\n   <coefh value=\"1.0\" />\n"
       << "   <cflnumber value=\"0.2\" />\n  </constantsdef>\n"
       << "  <mkconfig boundcount=\"240\" fluidcount=\"9\" />\n  <geometry>\n"
       << "   <definition dp=\"" << dp << "\">\n"
       << "    <pointmin x=\"-1\" y=\"" << (two_d ? 0 : -1) << "\" z=\"-1\" />\n"
       << "    <pointmax x=\"5\" y=\"" << (two_d ? 0 : 5) << "\" z=\"5\" />\n   </definition>\n"
       << "   <commands>\n    <mainlist>\n" << mainlist << "\n    </mainlist>\n   </commands>\n"
       << "  </geometry>\n" << casedef_extra << "\n </casedef>\n <execution>\n"
       << "  <special>\n" << special << "\n  </special>\n  <parameters>\n"
       << "   <parameter key=\"Visco\" value=\"0.1\" />\n   <parameter key=\"TimeMax\" value=\"1\" />\n"
       << "   <parameter key=\"TimeOut\" value=\"0.1\" />\n" << parameters << "\n  </parameters>\n"
       << " </execution>\n</case>\n";
    return os.str();
}

gencase::GeneratedCase buildCase(const std::string& def_path, double dp) {
    gencase::GencaseOptions opt;
    opt.definition = def_path;
    opt.output_base = fs::path(def_path).parent_path().string() + "/out/Case";
    opt.dp_override = dp;
    std::ostringstream log;
    gencase::CaseBuilder b(opt, log);
    return b.build();
}

CommandResult runGencase(const std::string& args) {
    const std::string cmd = std::string(SEASPRING_GENCASE_BIN) + " " + args + " 2>&1";
    CommandResult r{-1, ""};
    FILE* pipe = ::popen(cmd.c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    while (std::fgets(buf, sizeof buf, pipe)) r.output += buf;
    const int status = ::pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::unique_ptr<gencase::CaseBuilder> buildCaseKeepBuilder(const std::string& def_path,
                                                           std::ostream& log, double dp) {
    gencase::GencaseOptions opt;
    opt.definition = def_path;
    opt.output_base = fs::path(def_path).parent_path().string() + "/out/Case";
    opt.dp_override = dp;
    auto b = std::make_unique<gencase::CaseBuilder>(opt, log);
    b->build();
    return b;
}

std::string buildError(const std::string& def_path, double dp) {
    try {
        buildCase(def_path, dp);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

int lineOf(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    if (at == std::string::npos) return 0;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

std::vector<std::string> listFiles(const std::string& dir) {
    std::vector<std::string> out;
    std::error_code ec;
    if (!fs::exists(dir, ec)) return out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) out.push_back(fs::relative(e.path(), dir).string());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace seaspring::test
