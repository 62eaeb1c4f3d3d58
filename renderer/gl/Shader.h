#pragma once
// GLSL programs built from files under shaders/, with a small #include mechanism.
//
// `#include "file.glsl"` (or "shared.h") is resolved against the including file's folder, then
// shaders/include/. Each file is included once per stage. The expanded source carries #line
// directives whose source-string number indexes the program's file table, so a compile error
// "3:17(2): error: ..." is reported as "shaders/include/brdf.glsl:17: error: ...".
//
// A Program keeps its last good GL program: reload() that fails to compile or link logs the
// error and leaves the running program untouched.

#include "gl/Handle.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace lit {
class Log;
}

namespace lit::gl {

struct ShaderStageSource {
    GLenum stage;       // GL_VERTEX_SHADER, ...
    std::string file;   // relative to the shader root, e.g. "gbuffer.frag.glsl"
};

// Expands #include directives. Throws GlError naming the file and line of a bad include.
// `files` receives every file read, in source-string order (index 0 is `file` itself).
std::string expandIncludes(const std::filesystem::path& root, const std::string& file,
                           const std::string& defines, std::vector<std::filesystem::path>& files);

// Rewrites "N:LINE(COL): message" lines from the GLSL compiler into "path:LINE: message".
std::string mapCompilerLog(const std::string& log, const std::vector<std::filesystem::path>& files);

class Program {
public:
    Program() = default;
    // Builds the program now; throws GlError with file:line messages if the first build fails.
    Program(std::filesystem::path root, std::string label, std::vector<ShaderStageSource> stages,
            std::string defines = {});

    // Rebuilds from the files. On failure logs the error, keeps the previous program and
    // returns false.
    bool reload(Log& log);
    // True when any file this program was built from changed on disk since the last build.
    bool sourcesChanged() const;

    GLuint id() const { return program_.id(); }
    void use() const { glUseProgram(program_.id()); }
    explicit operator bool() const { return static_cast<bool>(program_); }
    const std::string& label() const { return label_; }

    // Uniform helpers (glProgramUniform*, DSA). Unknown names are ignored, as GL does.
    GLint location(const char* name) const;
    void set(const char* name, int value) const;
    void set(const char* name, float value) const;
    void set(const char* name, const float* mat4) const;

private:
    // Returns a linked program or throws GlError with the mapped log.
    ProgramHandle build(std::map<std::filesystem::path, std::filesystem::file_time_type>& stamps) const;

    std::filesystem::path root_;
    std::string label_;
    std::vector<ShaderStageSource> stages_;
    std::string defines_;
    ProgramHandle program_;
    std::map<std::filesystem::path, std::filesystem::file_time_type> stamps_;
};

}  // namespace lit::gl
