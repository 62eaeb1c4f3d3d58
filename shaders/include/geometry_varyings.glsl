// What gbuffer.vert.glsl passes on to the fragment shaders that draw scene geometry from the
// camera (the G-buffer, the transmissive sheets and their IDs).
in VertexData {
    vec3 worldPosition;
    vec3 worldNormal;
    vec4 uv;  // xy TEXCOORD_0, zw TEXCOORD_1
    vec4 worldTangent;
    vec3 worldMotion;  // the world position minus the last frame's (gbuffer.vert.glsl, uPreviousModel)
} fs;
