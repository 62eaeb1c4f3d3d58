#pragma once
#include <string>

namespace lit {

class Log;

namespace gl {

// Checks the current context is OpenGL 4.5 core with what Lit needs (compute shaders, image
// load/store, 3D textures, timer queries). Throws GlError listing what is missing.
void requireCapabilities();

// Routes KHR_debug messages into `log` (synchronous, so the log line follows the call that
// caused it). `log` must outlive the context's use of the callback.
void installDebugOutput(Log& log);

std::string contextDescription();  // "4.5 (Core Profile) Mesa 22.3.6 — llvmpipe (...)"

}  // namespace gl
}  // namespace lit
