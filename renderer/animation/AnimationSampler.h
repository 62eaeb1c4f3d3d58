#pragma once
// One glTF animation sampler evaluated at a time: the key times (input) and values (output) of a
// translation, rotation or scale channel, interpolated as glTF 2.0 §3.11 and Appendix C say:
//
//   STEP         the value of the last key at or before t
//   LINEAR       lerp of the two keys around t; rotations slerp along the shorter arc
//   CUBICSPLINE  cubic Hermite between the two keys, each key stored as (in-tangent, value,
//                out-tangent), the tangents multiplied by the keys' interval t_{k+1} − t_k
//
// Before the first key the sampler holds the first value, after the last the last value (glTF
// leaves the clamping to the player; Blender and three.js clamp). Rotations come out unit length
// (a cubic spline or a lerp of unit quaternions is not). CPU only; it reads the caller's arrays
// (no copy), so it is cheap to make for each evaluation.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <optional>
#include <span>
#include <string_view>

namespace lit {

enum class Interpolation { Step, Linear, CubicSpline };

// "STEP", "LINEAR", "CUBICSPLINE" (glTF's names, case as written); nullopt for any other text.
std::optional<Interpolation> parseInterpolation(std::string_view name);

class AnimationSampler {
public:
    // `times` ascending, in seconds; `values` `components` floats per key (three times as many for
    // CUBICSPLINE). Throws std::invalid_argument when there are no keys, `components` is not 1..4,
    // or the value count does not match the keys.
    AnimationSampler(std::span<const float> times, std::span<const float> values, int components,
                     Interpolation interpolation);

    // The value at `seconds`; components past `components` are 0.
    glm::vec4 sample(double seconds) const;
    // A rotation channel (4 components, x y z w as glTF stores them), normalised.
    glm::quat sampleRotation(double seconds) const;

    float startTime() const { return times_.front(); }
    float endTime() const { return times_.back(); }

private:
    glm::vec4 value(std::size_t key, std::size_t part) const;  // part: 0 in-tangent, 1 value, 2 out-tangent (cubic)
    glm::vec4 keyValue(std::size_t key) const;                   // the key's value, whatever the layout
    // The key k with times[k] <= seconds < times[k + 1] and the fraction of the way to k + 1, for a
    // time strictly inside the keys.
    std::size_t segment(double seconds, float& fraction) const;

    std::span<const float> times_;
    std::span<const float> values_;
    std::size_t components_;
    Interpolation interpolation_;
};

// glTF Appendix C's slerp of two unit quaternions along the shorter arc (the second negated when
// their dot product is negative), falling back to a normalised lerp when they are nearly equal.
glm::quat slerpShortest(glm::quat a, glm::quat b, float fraction);

}  // namespace lit
