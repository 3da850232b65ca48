// SeaSpring — MIT licence.
/// \file error.cpp
#include "core/error.h"

namespace seaspring {

std::string formatLocation(const std::string& file, int line, const std::string& message) {
    std::ostringstream os;
    os << file;
    if (line > 0) os << ":" << line;
    os << ": " << message;
    return os.str();
}

void throwInputError(const std::string& file, int line, const std::string& message) {
    throw Error(formatLocation(file, line, message));
}

}  // namespace seaspring
