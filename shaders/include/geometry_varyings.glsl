// What gbuffer.vert.glsl passes on to the fragment shaders that draw scene geometry from the
// camera (the G-buffer, the transmissive sheets and their IDs).
in VertexData {
    vec3 worldPosition;
    vec3 worldNormal;
    vec2 uv;
    vec4 worldTangent;
} fs;
