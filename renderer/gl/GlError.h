#pragma once
#include <stdexcept>
#include <string>

namespace lit::gl {

// A driver or data failure that the caller can report and survive (shader errors, incomplete
// framebuffers, missing GL features). Programmer mistakes are asserts, not GlErrors.
class GlError : public std::runtime_error {
public:
    explicit GlError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace lit::gl
