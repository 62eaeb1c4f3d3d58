#pragma once
// What every pass shares: the shader root to build programs from, and a way for the renderer
// to reach each pass's programs for hot reload.

#include "gl/Objects.h"
#include "gl/Shader.h"

#include <filesystem>
#include <vector>

namespace lit {

class Pass {
public:
    virtual ~Pass() = default;
    // The programs this pass owns (for hot reload).
    virtual std::vector<gl::Program*> programs() = 0;
};

// The full-screen triangle of fullscreen.vert.glsl. Core profile needs a bound vertex array
// even when no attribute is read, so each full-screen pass owns one of these.
class FullscreenTriangle {
public:
    FullscreenTriangle() : vertexArray_("fullscreen triangle") {}
    void draw() const {
        vertexArray_.bind();
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

private:
    gl::VertexArray vertexArray_;
};

}  // namespace lit
