// SeaSpring — MIT licence.
/// \file test_files.h
/// \brief Small helpers the tests share (header-only, any test executable): reading a
///        ';'-separated CSV file (gauges, ledger, seaspring-post output) and running a program
///        through the shell with its output captured.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace seaspring::test {

/// The rows of a ';'-separated file with one header line (`header` gets it), as text.
inline std::vector<std::vector<std::string>> readCsv(const std::string& path, std::string& header) {
    std::ifstream f(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    if (!std::getline(f, header)) return rows;
    while (std::getline(f, line)) {
        std::vector<std::string> row;
        std::stringstream s(line);
        std::string item;
        while (std::getline(s, item, ';')) row.push_back(item);
        rows.push_back(row);
    }
    return rows;
}

struct ProgramRun {
    int status = -1;  ///< exit status (-1: did not exit normally)
    std::string out;  ///< what it wrote to stdout (and whatever `command` redirects there)
};

/// Runs `command` through the shell with OMP_WAIT_POLICY=passive, stdout captured.
inline ProgramRun runProgram(const std::string& command) {
    ProgramRun p;
    FILE* pipe = ::popen(("OMP_WAIT_POLICY=passive " + command).c_str(), "r");
    if (pipe == nullptr) return p;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) p.out.append(buf, n);
    const int status = ::pclose(pipe);
    p.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return p;
}

}  // namespace seaspring::test
