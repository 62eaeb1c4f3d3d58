#pragma once
// glTF's KHR_lights_punctual is photometric (point/spot: candela = lm/sr, directional:
// lux = lm/m²); Lit renders radiometrically (W/sr, W/m², radiance in W/(sr·m²)). One luminous
// efficacy converts between them everywhere: the loader divides by it, the writer multiplies,
// and the renderer and the reference path tracer read the Scene's radiometric numbers.
// docs/UNITS.md explains the choice.

namespace lit {

// Luminous efficacy of 555 nm light (lm/W), the factor Blender's glTF exporter uses for its
// default "Standard" lighting mode (io_scene_gltf2, PBR_WATTS_TO_LUMENS = 683).
inline constexpr double kLumensPerWatt = 683.0;

// cd → W/sr, lx → W/m².
inline float radiometricFromPhotometric(double photometric) {
    return static_cast<float>(photometric / kLumensPerWatt);
}
// W/sr → cd, W/m² → lx.
inline double photometricFromRadiometric(float radiometric) {
    return static_cast<double>(radiometric) * kLumensPerWatt;
}

}  // namespace lit
