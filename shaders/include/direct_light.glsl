// The direct light of a surface from every punctual light with shadow-map visibility, split into
// the two direct terms (docs/MATERIALS.md, direct_lighting.frag.glsl):
//   diffuse  = Σ V·E·(albedo/π · t_s · b + f_sheen · b)·(n·l)
//   specular = Σ V·E·(f_spec · t_s · b·(n·l) + cc·f_coat·(n_c·l))
// with t_s what a sheen leaves of the base and b = 1 − cc·Fc(n_c·v) what a clear coat lets through;
// n_c is the coat's normal (coatNormal: its own map, else n).
// `albedo` is the diffuse albedo (a transmissive sheet passes its (1 − t) share). Used by the
// deferred direct pass and the sheet pass. Needs gbuffer.glsl (Surface, the sheen table) and
// lights.glsl. Each lobe is widened by the pixel's footprint (Surface::footprint: specular
// anti-aliasing).
void directLight(Surface s, vec3 n, vec3 v, vec3 albedo, float shadowNormalOffset, out vec3 diffuse, out vec3 specular) {
    float alpha = alphaFromRoughness(widenedRoughness(s.roughness, s.footprint));
    float NdotV = max(dot(n, v), 0.0);
    vec3 nc = coatNormal(s, n, v);
    float coatScale = clearcoatBaseScale(s.clearcoat, max(dot(nc, v), 0.0));
    float base = coatScale * sheenBaseScale(s, NdotV);
    float coatAlpha = alphaFromRoughness(widenedRoughness(s.clearcoatRoughness, s.footprint));
    bool sheen = max(s.sheenColor.r, max(s.sheenColor.g, s.sheenColor.b)) > 0.0;
    float alphaSheen = sheenAlpha(s.sheenRoughness);
    diffuse = vec3(0.0);
    specular = vec3(0.0);
    int count = frame.counts.x;
    for (int i = 0; i < count; ++i) {
        GpuLight light = lights[i];
        LightSample ls = sampleLight(light, s.position);
        float NdotL = dot(n, ls.l);
        float NcdotL = s.clearcoat > 0.0 ? dot(nc, ls.l) : 0.0;
        if (max(NdotL, NcdotL) <= 0.0 || max(ls.radiance.r, max(ls.radiance.g, ls.radiance.b)) <= 0.0) continue;
        vec3 visibility = shadowVisibility(light, s.position, n, frame.exposure.y, shadowNormalOffset);
        if (max(visibility.r, max(visibility.g, visibility.b)) <= 0.0) continue;
        if (NcdotL > 0.0)
            specular += ls.radiance * visibility * (NcdotL * s.clearcoat) *
                        specularBrdf(nc, v, ls.l, kClearcoatF0, 1.0, coatAlpha);
        if (NdotL <= 0.0) continue;
        vec3 E = ls.radiance * visibility * NdotL;
        diffuse += E * albedo * (base / PI);
        if (sheen) {
            vec3 h = normalize(v + ls.l);
            diffuse += E * s.sheenColor *
                       (D_Charlie(max(dot(n, h), 0.0), alphaSheen) * V_Neubelt(NdotL, max(NdotV, 1e-4)) * coatScale);
        }
        specular += E * specularBrdf(n, v, ls.l, s.f0, s.f90, alpha) * base;
    }
}
