#pragma once
// A Log that keeps its messages for the test to read (recent(), countAtLeast) and prints nothing.

#include <cstddef>

#include "Log.h"

namespace lit::testing {

struct QuietLog : Log {
    QuietLog() {
        setSink([](const LogMessage&) {});
    }
    std::size_t warnings() const { return countAtLeast(LogLevel::Warning); }
};

}  // namespace lit::testing
