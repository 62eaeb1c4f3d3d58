#include "context/HeadlessContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace lit {

namespace {

const char* eglErrorName(EGLint error) {
    switch (error) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
        case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
        case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
        default: return "unknown EGL error";
    }
}

// "step failed (EGL_BAD_MATCH)" with the error of the call that just failed.
std::string failure(std::string_view step) {
    const EGLint error = eglGetError();
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(error));
    return std::string(step) + " failed (" + eglErrorName(error) + ", " + code + ")";
}

// Whole-word search in a space-separated extension string (a prefix match would confuse
// EGL_EXT_platform_base with EGL_EXT_platform_base_foo).
bool hasExtension(const char* extensions, std::string_view name) {
    if (!extensions) return false;
    std::string_view rest(extensions);
    while (!rest.empty()) {
        const std::size_t end = rest.find(' ');
        if (rest.substr(0, end) == name) return true;
        if (end == std::string_view::npos) break;
        rest.remove_prefix(end + 1);
    }
    return false;
}

}  // namespace

struct HeadlessContext::State {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;  // a 1×1 pbuffer only where surfaceless contexts are missing
    bool initialized = false;
    std::string description;

    State() = default;
    State(const State&) = delete;
    State& operator=(const State&) = delete;

    // Releases what was made, in reverse order. Note: Mesa hands out one display per platform
    // and process, so terminating it ends every context on it; Lit makes one context per process.
    ~State() {
        if (display == EGL_NO_DISPLAY) return;
        if (context != EGL_NO_CONTEXT) {
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display, context);
        }
        if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
        if (initialized) eglTerminate(display);
        eglReleaseThread();
    }

    // Initialises `display` and makes a current GL 4.5 core context on it. Throws
    // std::runtime_error naming the failed step.
    void makeContext(EGLDisplay candidate) {
        display = candidate;
        if (display == EGL_NO_DISPLAY) throw std::runtime_error(failure("getting the display"));
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display, &major, &minor)) throw std::runtime_error(failure("eglInitialize"));
        initialized = true;
        if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(failure("eglBindAPI(EGL_OPENGL_API)"));

        const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
        const bool noConfig = hasExtension(extensions, "EGL_KHR_no_config_context") ||
                              hasExtension(extensions, "EGL_MESA_configless_context");
        const bool surfaceless = hasExtension(extensions, "EGL_KHR_surfaceless_context");

        EGLConfig config = EGL_NO_CONFIG_KHR;
        if (!noConfig || !surfaceless) {
            const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                               EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                               EGL_NONE};
            EGLint count = 0;
            if (!eglChooseConfig(display, configAttributes, &config, 1, &count))
                throw std::runtime_error(failure("eglChooseConfig"));
            if (count == 0) throw std::runtime_error("eglChooseConfig found no RGBA8 pbuffer config for desktop OpenGL");
        }

        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
        if (context == EGL_NO_CONTEXT) throw std::runtime_error(failure("eglCreateContext (OpenGL 4.5 core)"));

        if (!surfaceless) {
            const EGLint pbufferAttributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
            surface = eglCreatePbufferSurface(display, config, pbufferAttributes);
            if (surface == EGL_NO_SURFACE) throw std::runtime_error(failure("eglCreatePbufferSurface"));
        }
        if (!eglMakeCurrent(display, surface, surface, context)) throw std::runtime_error(failure("eglMakeCurrent"));
    }
};

HeadlessContext::HeadlessContext() {
    // Client extensions (EGL_NO_DISPLAY) say which platforms can be asked for by name. The query
    // fails with EGL_BAD_DISPLAY on EGL 1.4 without EGL_EXT_client_extensions: then only the
    // default display remains.
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client) eglGetError();
    const bool platformBase = hasExtension(client, "EGL_EXT_platform_base");

    struct Platform {
        const char* name;
        bool available;
        std::function<EGLDisplay()> display;
    };
    const Platform platforms[] = {
        {"surfaceless", platformBase && hasExtension(client, "EGL_MESA_platform_surfaceless"),
         [] { return eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr); }},
        {"device", platformBase && hasExtension(client, "EGL_EXT_platform_device") && hasExtension(client, "EGL_EXT_device_enumeration"),
         []() -> EGLDisplay {
             EGLDeviceEXT devices[16];
             EGLint count = 0;
             if (!eglQueryDevicesEXT(16, devices, &count)) throw std::runtime_error(failure("eglQueryDevicesEXT"));
             if (count == 0) throw std::runtime_error("eglQueryDevicesEXT found no EGL device");
             return eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
         }},
        {"default display", true, [] { return eglGetDisplay(EGL_DEFAULT_DISPLAY); }},
    };

    std::string errors;
    for (const Platform& platform : platforms) {
        if (!platform.available) {
            errors += std::string(errors.empty() ? "" : "; ") + platform.name + ": not supported by this EGL";
            continue;
        }
        auto state = std::make_unique<State>();
        try {
            state->makeContext(platform.display());
        } catch (const std::runtime_error& e) {
            errors += std::string(errors.empty() ? "" : "; ") + platform.name + ": " + e.what();
            continue;  // `state` releases whatever was made before the failure
        }
        const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
        const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        state->description = std::string("EGL ") + platform.name + ": " + (version ? version : "?") + ", " +
                             (renderer ? renderer : "?");
        state_ = std::move(state);
        return;
    }
    throw std::runtime_error("cannot create a headless OpenGL 4.5 core context through EGL (" + errors + ")");
}

HeadlessContext::~HeadlessContext() = default;

std::string HeadlessContext::description() const { return state_->description; }

}  // namespace lit
