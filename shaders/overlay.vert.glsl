#version 450 core
// Overlay lines (OverlayPass): world-space end points with a colour each.
#include "frame.glsl"

layout(location = 0) in vec3 inPosition;  // world (m)
layout(location = 1) in vec4 inColor;     // linear RGBA

out vec4 vColor;

void main() {
    vColor = inColor;
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
}
