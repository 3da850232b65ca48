// SeaSpring — MIT licence.
/// \file error_expect.h
/// \brief Test helpers for error paths: the message of the seaspring::Error a call throws,
///        and EXPECT_HAS(text, part) for "the message names this".
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.h"

namespace seaspring::test {

/// Message of the seaspring::Error thrown by f (a test failure if none is thrown).
inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a seaspring::Error";
    return "";
}

}  // namespace seaspring::test

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << "message: " << (text)
