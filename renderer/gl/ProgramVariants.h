#pragma once
// A program in compile-time variants, each a set of #defines, built on first use. llvmpipe runs
// both sides of a branch, a uniform one included, so code that a setting or the scene switches
// off still costs its texture reads unless it is compiled out: the cone features (ConeProgram)
// and the kinds of shadow map the lights use (ShadowKinds, LightSetup.h) pick variants this way.

#include "gl/Shader.h"

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace lit::gl {

template <std::size_t N>
class ProgramVariants {
public:
    ProgramVariants() = default;
    // `defines` go before every variant's own.
    ProgramVariants(std::filesystem::path root, std::string label, std::vector<ShaderStageSource> stages,
                    std::string defines = {})
        : root_(std::move(root)), label_(std::move(label)), stages_(std::move(stages)), defines_(std::move(defines)) {}

    // The variant of `key` (index() < N), built now from key.defines() and named with key.label()
    // if it was not yet (throws GlError if that fails). A built variant costs no string work, so
    // this is cheap on every frame.
    template <typename Key>
    const Program& get(const Key& key) {
        Program& program = variants_.at(static_cast<std::size_t>(key.index()));
        if (!program) program = Program(root_, label_ + key.label(), stages_, defines_ + key.defines());
        return program;
    }
    // True for a default-constructed one (no program description).
    bool empty() const { return stages_.empty(); }
    // The variants built so far (for hot reload).
    void appendBuilt(std::vector<Program*>& out) {
        for (Program& program : variants_)
            if (program) out.push_back(&program);
    }
    std::vector<Program*> built() {
        std::vector<Program*> out;
        appendBuilt(out);
        return out;
    }

private:
    std::filesystem::path root_;
    std::string label_;
    std::vector<ShaderStageSource> stages_;
    std::string defines_;
    std::array<Program, N> variants_;
};

}  // namespace lit::gl
