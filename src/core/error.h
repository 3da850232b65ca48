// SeaSpring — MIT licence.
/// \file error.h
/// \brief The project's one exception type and the CHECK macros.
///
/// Every user-facing error names where it comes from: a source file and line for
/// input errors (the case XML, a motion file), the code location for internal ones.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace seaspring {

/// Error raised for bad input or an internal failure. `what()` is the full,
/// user-readable message ("file:line: message").
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// Builds "file:line: message" (line omitted when 0).
std::string formatLocation(const std::string& file, int line, const std::string& message);

/// Throws an Error for bad input at file:line.
[[noreturn]] void throwInputError(const std::string& file, int line, const std::string& message);

namespace detail {
template <typename... Args>
std::string concat(Args&&... args) {
    std::ostringstream os;
    os.precision(15);
    (os << ... << args);
    return os.str();
}
}  // namespace detail

}  // namespace seaspring

/// Internal consistency check: throws seaspring::Error naming the code location.
#define SEASPRING_CHECK(cond, ...)                                                        \
    do {                                                                                  \
        if (!(cond))                                                                      \
            throw ::seaspring::Error(::seaspring::formatLocation(                         \
                __FILE__, __LINE__, ::seaspring::detail::concat(__VA_ARGS__)));           \
    } while (0)
