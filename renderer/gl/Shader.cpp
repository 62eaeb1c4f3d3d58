#include "gl/Shader.h"

#include "Log.h"
#include "gl/GlError.h"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace lit::gl {

namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw GlError("cannot read shader file " + path.string());
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

const char* stageName(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER: return "vertex";
        case GL_GEOMETRY_SHADER: return "geometry";
        case GL_FRAGMENT_SHADER: return "fragment";
        case GL_COMPUTE_SHADER: return "compute";
        case GL_TESS_CONTROL_SHADER: return "tessellation control";
        case GL_TESS_EVALUATION_SHADER: return "tessellation evaluation";
    }
    return "unknown";
}

struct Expander {
    fs::path root;
    std::vector<fs::path>& files;
    std::set<fs::path> included;

    int indexOf(const fs::path& p) {
        for (std::size_t i = 0; i < files.size(); ++i)
            if (files[i] == p) return static_cast<int>(i);
        files.push_back(p);
        return static_cast<int>(files.size() - 1);
    }

    // Appends `path` expanded into `out`. `versionDone` is set once the #version line passed.
    void expand(const fs::path& path, std::ostringstream& out, const std::string& defines, bool top) {
        const int index = indexOf(path);
        included.insert(fs::weakly_canonical(path));
        std::istringstream in(readFile(path));
        std::string line;
        int lineNo = 0;
        bool versionSeen = !top;
        // Only quoted includes are ours; <...> includes belong to C++ (shared.h includes glm inside
        // #ifdef __cplusplus) and sit in groups the GLSL preprocessor skips.
        static const std::regex includeRe(R"(^\s*#\s*include\s+\"([^\"]+)\"\s*$)");
        if (!top) out << "#line 1 " << index << "\n";
        while (std::getline(in, line)) {
            ++lineNo;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::smatch m;
            if (std::regex_match(line, m, includeRe)) {
                const fs::path target = resolve(path, m[1].str(), lineNo);
                if (!included.count(fs::weakly_canonical(target))) expand(target, out, defines, false);
                out << "#line " << (lineNo + 1) << " " << index << "\n";
                continue;
            }
            out << line << "\n";
            if (!versionSeen && line.find("#version") != std::string::npos) {
                versionSeen = true;
                out << defines;
                out << "#line " << (lineNo + 1) << " " << index << "\n";
            }
        }
        if (top && !versionSeen)
            throw GlError(path.string() + ":1: error: shader has no #version line");
    }

    fs::path resolve(const fs::path& from, const std::string& name, int lineNo) const {
        const fs::path local = from.parent_path() / name;
        if (fs::exists(local)) return local;
        const fs::path shared = root / "include" / name;
        if (fs::exists(shared)) return shared;
        throw GlError(from.string() + ":" + std::to_string(lineNo) + ": error: cannot find include \"" + name +
                      "\" (looked in " + from.parent_path().string() + " and " + (root / "include").string() + ")");
    }
};

}  // namespace

std::string expandIncludes(const fs::path& root, const std::string& file, const std::string& defines,
                           std::vector<fs::path>& files) {
    Expander expander{root, files, {}};
    std::ostringstream out;
    expander.expand(root / file, out, defines, true);
    return out.str();
}

std::string mapCompilerLog(const std::string& log, const std::vector<fs::path>& files) {
    // Mesa: "0:12(3): error: ..."; NVIDIA: "0(12) : error ...". Both start with the string index.
    static const std::regex mesaRe(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex nvRe(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::istringstream in(log);
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        std::size_t index = 0;
        std::string lineNo, message;
        if (std::regex_match(line, m, mesaRe)) {
            index = std::stoul(m[1].str());
            lineNo = m[2].str();
            message = m[4].str();
        } else if (std::regex_match(line, m, nvRe)) {
            index = std::stoul(m[1].str());
            lineNo = m[2].str();
            message = m[3].str();
        } else {
            if (!line.empty()) out << line << "\n";
            continue;
        }
        const std::string file = index < files.size() ? files[index].string() : "<string " + m[1].str() + ">";
        out << file << ":" << lineNo << ": " << message << "\n";
    }
    return out.str();
}

Program::Program(fs::path root, std::string label, std::vector<ShaderStageSource> stages, std::string defines)
    : root_(std::move(root)), label_(std::move(label)), stages_(std::move(stages)), defines_(std::move(defines)) {
    program_ = build(stamps_);
}

ProgramHandle Program::build(std::map<fs::path, fs::file_time_type>& stamps) const {
    ProgramHandle program(glCreateProgram());
    std::vector<ShaderHandle> shaders;
    for (const ShaderStageSource& stage : stages_) {
        std::vector<fs::path> files;
        const std::string source = expandIncludes(root_, stage.file, defines_, files);
        for (const fs::path& f : files) {
            std::error_code ec;
            stamps[f] = fs::last_write_time(f, ec);
        }
        ShaderHandle shader(glCreateShader(stage.stage));
        const char* text = source.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) {
            GLint length = 0;
            glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
            std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
            glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
            throw GlError("shader program '" + label_ + "': " + stageName(stage.stage) + " shader " + stage.file +
                          " failed to compile:\n" + mapCompilerLog(log.c_str(), files));
        }
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(program.id());
    for (const ShaderHandle& s : shaders) glDetachShader(program.id(), s.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        throw GlError("shader program '" + label_ + "' failed to link:\n" + std::string(log.c_str()));
    }
    program.label(label_);
    return program;
}

bool Program::reload(Log& log) {
    std::map<fs::path, fs::file_time_type> stamps;
    try {
        ProgramHandle fresh = build(stamps);
        program_ = std::move(fresh);
        stamps_ = std::move(stamps);
        log.info("reloaded shader program '" + label_ + "'");
        return true;
    } catch (const GlError& e) {
        // Remember the broken files' times so we do not retry until they change again.
        for (auto& [file, time] : stamps) stamps_[file] = time;
        log.error(std::string(e.what()) + "\n(keeping the last good version of '" + label_ + "')");
        return false;
    }
}

bool Program::sourcesChanged() const {
    for (const auto& [file, time] : stamps_) {
        std::error_code ec;
        const auto now = fs::last_write_time(file, ec);
        if (ec || now != time) return true;
    }
    return false;
}

GLint Program::location(const char* name) const { return glGetUniformLocation(program_.id(), name); }
void Program::set(const char* name, int value) const { glProgramUniform1i(program_.id(), location(name), value); }
void Program::set(const char* name, float value) const { glProgramUniform1f(program_.id(), location(name), value); }
void Program::set(const char* name, const float* mat4) const {
    glProgramUniformMatrix4fv(program_.id(), location(name), 1, GL_FALSE, mat4);
}

}  // namespace lit::gl
