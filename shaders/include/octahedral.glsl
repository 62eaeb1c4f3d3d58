// Unit vectors in two numbers (the G-buffer's coat normal, the indirect passes' guides).
// Octahedral unit-vector encoding (Cigolle et al. 2014, "A Survey of Efficient Representations
// for Independent Unit Vectors", JCGT 3(2)); 16 bits per coordinate keep it within 0.01°.
vec2 octEncode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 signs = mix(vec2(-1.0), vec2(1.0), greaterThanEqual(n.xy, vec2(0.0)));
    return n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * signs;
}
vec3 octDecode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy += mix(vec2(t), vec2(-t), greaterThanEqual(n.xy, vec2(0.0)));
    return normalize(n);
}
