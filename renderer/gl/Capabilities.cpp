#include "gl/Capabilities.h"

#include "Log.h"
#include "gl/GlError.h"
#include <shared.h>

#include <epoxy/gl.h>

#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace lit::gl {

namespace {

std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? std::string(text) : std::string("(unknown)");
}

GLint glInteger(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

// "compatibility", "core" or "legacy" (before 3.2 there are no profiles).
std::string profileName(int version) {
    if (version < 32) return "legacy";
    const GLint mask = glInteger(GL_CONTEXT_PROFILE_MASK);
    if (mask & GL_CONTEXT_CORE_PROFILE_BIT) return "core";
    if (mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) return "compatibility";
    return "unknown profile";
}

// Adds "what (have N, need M)" to `missing` when a limit is below what Lit uses.
void requireAtLeast(std::vector<std::string>& missing, const char* what, GLenum limit, GLint need) {
    const GLint have = glInteger(limit);
    if (have < need) missing.push_back(std::string(what) + " (have " + std::to_string(have) + ", need " + std::to_string(need) + ")");
}

const char* sourceName(GLenum source) {
    switch (source) {
        case GL_DEBUG_SOURCE_API: return "api";
        case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
        case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
        case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
        case GL_DEBUG_SOURCE_APPLICATION: return "application";
        default: return "other";
    }
}

const char* typeName(GLenum type) {
    switch (type) {
        case GL_DEBUG_TYPE_ERROR: return "error";
        case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated behaviour";
        case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
        case GL_DEBUG_TYPE_PORTABILITY: return "portability";
        case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
        case GL_DEBUG_TYPE_MARKER: return "marker";
        default: return "other";
    }
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* userParam) {
    // Notifications (buffer placement hints, debug group push/pop) are chatty on llvmpipe and
    // NVIDIA alike and never point at a bug; they are also disabled at the source.
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    auto& log = *static_cast<Log*>(const_cast<void*>(userParam));
    const std::string text = std::string("GL ") + typeName(type) + " (" + sourceName(source) + ", id " +
                             std::to_string(id) + "): " +
                             (length >= 0 ? std::string(message, static_cast<std::size_t>(length)) : std::string(message));
    if (severity == GL_DEBUG_SEVERITY_HIGH)
        log.error(text);
    else
        log.warning(text);
}

}  // namespace

std::string contextDescription() {
    if (glGetString(GL_VERSION) == nullptr) return "no current OpenGL context";
    return glString(GL_VERSION) + " \u2014 " + glString(GL_RENDERER);
}

bool softwareRasterizer() {
    if (glGetString(GL_RENDERER) == nullptr) return false;
    const std::string renderer = glString(GL_RENDERER);
    for (const char* name : {"llvmpipe", "softpipe", "swrast"})
        if (renderer.find(name) != std::string::npos) return true;
    return false;
}

void requireCapabilities() {
    if (glGetString(GL_VERSION) == nullptr) throw GlError("Lit needs OpenGL 4.5 core, but no OpenGL context is current");
    if (!epoxy_is_desktop_gl())
        throw GlError("Lit needs desktop OpenGL 4.5 core; this context is OpenGL ES (" + contextDescription() + ")");

    const int version = epoxy_gl_version();  // major × 10 + minor
    const std::string profile = profileName(version);
    std::vector<std::string> missing;
    if (version < 45) missing.push_back("OpenGL 4.5 (direct state access, clip control)");
    if (profile != "core") missing.push_back("a core profile context");

    // Each limit is queried only where the feature exists, so an old context reports what is
    // missing instead of raising GL_INVALID_ENUM.
    if (version >= 43 || epoxy_has_gl_extension("GL_ARB_compute_shader")) {
        requireAtLeast(missing, "compute work group invocations", GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, 512);  // 8×8×8 groups
        requireAtLeast(missing, "compute texture units", GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS, 32);  // bounce injection samples the voxel volumes and the six directional ones
    } else
        missing.push_back("compute shaders");
    if (version >= 42 || epoxy_has_gl_extension("GL_ARB_shader_image_load_store"))
        requireAtLeast(missing, "image units", GL_MAX_IMAGE_UNITS, 8);  // shared.h uses units 0..5
    else
        missing.push_back("image load/store");
    requireAtLeast(missing, "3D texture size", GL_MAX_3D_TEXTURE_SIZE, 256);  // voxel volumes up to 256³ by default
    requireAtLeast(missing, "combined texture units", GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, LIT_TEX_UNIT_COUNT);
    // Cone tracing (fragment) samples 17 textures (G-buffer, voxel volumes, the six anisotropic
    // ones, sky, specular table); desktop GPUs and llvmpipe have 32 per stage.
    requireAtLeast(missing, "fragment texture units", GL_MAX_TEXTURE_IMAGE_UNITS, 32);
    if (version >= 33 || epoxy_has_gl_extension("GL_ARB_timer_query")) {
        GLint bits = 0;
        glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
        if (bits == 0) missing.push_back("timer queries (GL_TIMESTAMP has 0 counter bits)");
    } else {
        missing.push_back("timer queries");
    }
    if (version < 43 && !epoxy_has_gl_extension("GL_KHR_debug")) missing.push_back("debug groups (KHR_debug)");
    while (glGetError() != GL_NO_ERROR) {
    }

    if (missing.empty()) return;
    std::string message = "Lit needs OpenGL 4.5 core; this context is " + std::to_string(version / 10) + "." +
                          std::to_string(version % 10) + " " + profile + " (" + contextDescription() + "); missing: ";
    for (std::size_t i = 0; i < missing.size(); ++i) message += (i ? ", " : "") + missing[i];
    throw GlError(message);
}

void installDebugOutput(Log& log) {
    if (epoxy_gl_version() < 43 && !epoxy_has_gl_extension("GL_KHR_debug")) {
        log.warning("GL debug output unavailable (needs OpenGL 4.3 or KHR_debug)");
        return;
    }
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous: the message is delivered inside the GL call that caused it, so the log line
    // follows the right call (and a debugger breakpoint in the callback has the right stack).
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr, GL_FALSE);
    glDebugMessageCallback(onDebugMessage, &log);
}

bool injectGlErrorIfRequested() {
    const char* request = std::getenv("LIT_TEST_GL_ERROR");
    if (request == nullptr || std::string_view(request) != "1") return false;
    // Buffer names are small integers handed out by glCreateBuffers; this one was never made.
    glBindBuffer(GL_ARRAY_BUFFER, 0x7fffffffu);
    return true;
}

}  // namespace lit::gl
