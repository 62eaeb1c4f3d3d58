#include "animation/AnimationSampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lit {

std::optional<Interpolation> parseInterpolation(std::string_view name) {
    if (name == "STEP") return Interpolation::Step;
    if (name == "LINEAR") return Interpolation::Linear;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    return std::nullopt;
}

AnimationSampler::AnimationSampler(std::span<const float> times, std::span<const float> values, int components,
                                   Interpolation interpolation)
    : times_(times), values_(values), components_(static_cast<std::size_t>(components)), interpolation_(interpolation) {
    if (times.empty()) throw std::invalid_argument("an animation sampler needs at least one key");
    if (components < 1 || components > 4)
        throw std::invalid_argument("an animation sampler has 1 to 4 components, not " + std::to_string(components));
    const std::size_t perKey = components_ * (interpolation == Interpolation::CubicSpline ? 3 : 1);
    if (values.size() != times.size() * perKey)
        throw std::invalid_argument("an animation sampler with " + std::to_string(times.size()) + " keys needs " +
                                    std::to_string(times.size() * perKey) + " values, not " +
                                    std::to_string(values.size()));
}

glm::vec4 AnimationSampler::value(std::size_t key, std::size_t part) const {
    const std::size_t parts = interpolation_ == Interpolation::CubicSpline ? 3 : 1;
    const std::size_t first = (key * parts + part) * components_;
    glm::vec4 out(0.0f);
    for (std::size_t c = 0; c < components_; ++c) out[static_cast<int>(c)] = values_[first + c];
    return out;
}

glm::vec4 AnimationSampler::keyValue(std::size_t key) const {
    return value(key, interpolation_ == Interpolation::CubicSpline ? 1 : 0);
}

std::size_t AnimationSampler::segment(double seconds, float& fraction) const {
    // The first key time greater than `seconds`; the caller has ruled out the ends.
    const auto next = std::upper_bound(times_.begin(), times_.end(), static_cast<float>(seconds));
    const std::size_t k = static_cast<std::size_t>(next - times_.begin()) - 1;
    const double t0 = times_[k], t1 = times_[k + 1];
    fraction = t1 > t0 ? static_cast<float>((seconds - t0) / (t1 - t0)) : 0.0f;
    return k;
}

glm::vec4 AnimationSampler::sample(double seconds) const {
    if (times_.size() == 1 || !(seconds > times_.front())) return keyValue(0);
    if (seconds >= times_.back()) return keyValue(times_.size() - 1);
    float s = 0.0f;
    const std::size_t k = segment(seconds, s);
    switch (interpolation_) {
    case Interpolation::Step: return keyValue(k);
    case Interpolation::Linear: return glm::mix(keyValue(k), keyValue(k + 1), s);
    case Interpolation::CubicSpline: {
        // glTF Appendix C: p(s) = (2s³ − 3s² + 1)v_k + td(s³ − 2s² + s)b_k + (−2s³ + 3s²)v_k+1 + td(s³ − s²)a_k+1,
        // b_k the out-tangent of key k, a_k+1 the in-tangent of key k + 1, td the interval.
        const float td = times_[k + 1] - times_[k];
        const float s2 = s * s, s3 = s2 * s;
        return (2.0f * s3 - 3.0f * s2 + 1.0f) * value(k, 1) + td * (s3 - 2.0f * s2 + s) * value(k, 2) +
               (-2.0f * s3 + 3.0f * s2) * value(k + 1, 1) + td * (s3 - s2) * value(k + 1, 0);
    }
    }
    return keyValue(k);
}

glm::quat AnimationSampler::sampleRotation(double seconds) const {
    const auto toQuat = [](glm::vec4 v) { return glm::quat(v.w, v.x, v.y, v.z); };  // glTF stores x, y, z, w
    const auto unit = [](glm::quat q) {
        const float length = glm::length(q);
        return length > 0.0f && std::isfinite(length) ? q / length : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    };
    if (interpolation_ == Interpolation::Linear && times_.size() > 1 && seconds > times_.front() &&
        seconds < times_.back()) {
        float s = 0.0f;
        const std::size_t k = segment(seconds, s);
        return slerpShortest(unit(toQuat(keyValue(k))), unit(toQuat(keyValue(k + 1))), s);
    }
    return unit(toQuat(sample(seconds)));
}

glm::quat slerpShortest(glm::quat a, glm::quat b, float fraction) {
    float cosAngle = glm::dot(a, b);
    if (cosAngle < 0.0f) {  // q and −q are the same rotation: take the one the shorter way round
        b = -b;
        cosAngle = -cosAngle;
    }
    if (cosAngle > 0.9995f) return glm::normalize(a * (1.0f - fraction) + b * fraction);  // sin(angle) ≈ 0
    const float angle = std::acos(cosAngle);
    const float sinAngle = std::sin(angle);
    return a * (std::sin((1.0f - fraction) * angle) / sinAngle) + b * (std::sin(fraction * angle) / sinAngle);
}

}  // namespace lit
