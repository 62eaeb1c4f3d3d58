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

// Test seam for the GL-error paths: when the environment variable LIT_TEST_GL_ERROR is "1",
// makes one invalid GL call (binding a buffer name that was never generated, which core
// profile answers with GL_INVALID_OPERATION) and returns true; otherwise does nothing. The
// programs call it once (lit-render after its frames, the editor when its context is set up)
// so tests can check what a real GL error does there: lit-render exits 1 and writes nothing,
// the editor logs it (docs/RELIABILITY.md).
bool injectGlErrorIfRequested();

std::string contextDescription();  // "4.5 (Core Profile) Mesa 22.3.6 — llvmpipe (...)"

// Whether the current context rasterizes on the CPU (Mesa llvmpipe, softpipe, swrast). There a
// pass's draws run when something first needs their result, so a pass's CPU time includes
// waiting for the passes before it (see Renderer's "GPU wait" scope).
bool softwareRasterizer();

}  // namespace gl
}  // namespace lit
