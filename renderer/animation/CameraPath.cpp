#include "animation/CameraPath.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <sstream>

namespace lit {

namespace {

// Knot step given to a segment whose two keys share a position (√metres): a zero step would
// divide by zero; this one makes the segment a point the camera slows into and out of.
constexpr double kMinKnotStep = 1e-9;
// Arc-length table resolution: cells per segment. 256 keeps the speed within a fraction of a
// percent of even for any segment shape a camera path has; the table costs a few µs to build.
constexpr int kCellsPerSegment = 256;
// A segment shorter than this fraction of the path stands still in constant-speed mode: it keeps
// its keyed duration (the camera pauses and turns) instead of taking no time at all.
constexpr double kStillFraction = 1e-6;
// A loop whose last key repeats the first within these tolerances closes at that key.
constexpr double kSamePositionMetres = 1e-5;
constexpr double kSameRotationDot = 1.0 - 1e-9;
constexpr double kSameFovRadians = 1e-6;
constexpr std::size_t kMaxFrames = 10'000'000;  // frameTimes() refuses more (a typo'd fps or time)

std::string number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Rotation vector (axis × angle, radians) of a unit quaternion, taking the shorter arc (angle ≤ π).
glm::dvec3 rotationVector(glm::dquat q) {
    if (q.w < 0.0) q = -q;
    const glm::dvec3 v(q.x, q.y, q.z);
    const double s = glm::length(v);
    // atan2 keeps full precision for small angles, where acos(w) would not.
    if (s < 1e-300) return 2.0 * v;
    return v * (2.0 * std::atan2(s, q.w) / s);
}

glm::dquat fromRotationVector(const glm::dvec3& r) {
    const double angle = glm::length(r);
    if (angle < 1e-300) return glm::dquat(1.0, 0.0, 0.0, 0.0);
    const glm::dvec3 axis = r / angle;
    return glm::dquat(std::cos(0.5 * angle), axis * std::sin(0.5 * angle));
}

// Spherical linear interpolation along the shorter arc.
glm::dquat slerpShort(const glm::dquat& a, const glm::dquat& b, double s) {
    return glm::normalize(a * fromRotationVector(s * rotationVector(glm::conjugate(a) * b)));
}

template <typename T>
T hermite(const T& p0, const T& p1, const T& m0, const T& m1, double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2.0 * s3 - 3.0 * s2 + 1.0) * p0 + (s3 - 2.0 * s2 + s) * m0 + (-2.0 * s3 + 3.0 * s2) * p1 + (s3 - s2) * m1;
}

// Monotone cubic (PCHIP) derivative at a knot between two segments of widths hPrev, hNext and
// slopes sPrev, sNext: the weighted harmonic mean of Fritsch & Butland (1984), zero at a local
// extremum. It never overshoots the data, so a strictly increasing sequence stays increasing.
double pchipDerivative(double hPrev, double hNext, double sPrev, double sNext) {
    if (sPrev * sNext <= 0.0) return 0.0;
    const double w1 = 2.0 * hNext + hPrev;
    const double w2 = hNext + 2.0 * hPrev;
    return (w1 + w2) / (w1 / sPrev + w2 / sNext);
}

// PCHIP derivatives at the boundaries of `slope.size()` segments; open ends take the end
// segment's slope, a loop wraps around.
std::vector<double> pchipRates(const std::vector<double>& width, const std::vector<double>& slope, bool loop) {
    const std::size_t segments = slope.size();
    std::vector<double> rate(segments + 1, 0.0);
    for (std::size_t b = 0; b <= segments; ++b) {
        const bool hasPrev = loop || b > 0;
        const bool hasNext = loop || b < segments;
        if (!hasPrev) {
            rate[b] = slope.front();
        } else if (!hasNext) {
            rate[b] = slope.back();
        } else {
            const std::size_t prev = (b + segments - 1) % segments;
            const std::size_t next = b % segments;
            rate[b] = pchipDerivative(width[prev], width[next], slope[prev], slope[next]);
        }
    }
    return rate;
}

// Time warp of easeInOut on normalized time x ∈ [0,1]: constant acceleration for a fraction
// `ramp` at each end, constant speed between (a trapezoidal speed profile; C1).
double easeInOut(double x, double ramp) {
    const double top = 1.0 / (1.0 - ramp);  // speed in the middle, so that the warp ends at 1
    if (x < ramp) return top * x * x / (2.0 * ramp);
    if (x <= 1.0 - ramp) return top * (x - 0.5 * ramp);
    const double rest = 1.0 - x;
    return 1.0 - top * rest * rest / (2.0 * ramp);
}

// The segment of `boundaries` (increasing) that holds x, clamped to the first and last.
std::size_t segmentIn(const std::vector<double>& boundaries, double x) {
    const auto above = std::upper_bound(boundaries.begin(), boundaries.end(), x);
    const std::size_t index =
        above == boundaries.begin() ? 0 : static_cast<std::size_t>(above - boundaries.begin()) - 1;
    return std::min(index, boundaries.size() - 2);
}

bool sameKey(const CameraKey& a, const CameraKey& b) {
    return glm::length(glm::dvec3(a.position) - glm::dvec3(b.position)) <= kSamePositionMetres &&
           std::abs(glm::dot(glm::dquat(a.rotation), glm::dquat(b.rotation))) >= kSameRotationDot &&
           std::abs(static_cast<double>(a.yfov) - b.yfov) <= kSameFovRadians;
}

}  // namespace

glm::mat4 CameraPose::world() const { return glm::translate(glm::mat4(1.0f), position) * glm::mat4_cast(rotation); }

void validateCameraKeys(const std::vector<CameraKey>& keys) {
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const CameraKey& key = keys[i];
        const std::string name = "key " + std::to_string(i) + ": ";
        if (!std::isfinite(key.time)) throw CameraPathError(name + "time is not a finite number");
        if (!finite(key.position)) throw CameraPathError(name + "position has a value that is not a finite number");
        const glm::quat& q = key.rotation;
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w))
            throw CameraPathError(name + "rotation has a value that is not a finite number");
        const double length = glm::length(glm::dquat(q));
        if (std::abs(length - 1.0) > kQuaternionLengthTolerance)
            throw CameraPathError(name + "rotation [" + number(q.x) + ", " + number(q.y) + ", " + number(q.z) + ", " +
                                  number(q.w) + "] is not a unit quaternion (length " + number(length) + ")");
        if (!std::isfinite(key.yfov) || !(key.yfov > 0.0f) || !(key.yfov < std::numbers::pi_v<float>))
            throw CameraPathError(name + "yfov " + number(key.yfov) + " is not between 0 and pi radians");
        if (i > 0 && !(key.time > keys[i - 1].time))
            throw CameraPathError(name + "time " + number(key.time) + " is not after key " + std::to_string(i - 1) +
                                  "'s time " + number(keys[i - 1].time));
    }
}

CameraPath::CameraPath(std::vector<CameraKey> keys, CameraPathOptions options) : options_(options) {
    setKeys(std::move(keys));
}

void CameraPath::setKeys(std::vector<CameraKey> keys) {
    validateCameraKeys(keys);
    for (CameraKey& key : keys) key.rotation = glm::normalize(key.rotation);
    keys_ = std::move(keys);
    rebuild();
}

void CameraPath::setOptions(const CameraPathOptions& options) {
    options_ = options;
    rebuild();
}

std::size_t CameraPath::insertKey(const CameraKey& key) {
    std::vector<CameraKey> keys = keys_;
    const auto at = std::lower_bound(keys.begin(), keys.end(), key.time,
                                     [](const CameraKey& k, float time) { return k.time < time; });
    if (at != keys.end() && at->time == key.time)
        throw CameraPathError("key " + std::to_string(at - keys.begin()) + " is already at time " + number(key.time));
    const std::size_t index = static_cast<std::size_t>(at - keys.begin());
    keys.insert(at, key);
    setKeys(std::move(keys));
    return index;
}

void CameraPath::removeKey(std::size_t index) {
    if (index >= keys_.size())
        throw std::out_of_range("no key " + std::to_string(index) + " (the path has " + std::to_string(keys_.size()) +
                                " keys)");
    std::vector<CameraKey> keys = keys_;
    keys.erase(keys.begin() + static_cast<std::ptrdiff_t>(index));
    setKeys(std::move(keys));
}

void CameraPath::setKey(std::size_t index, const CameraKey& key) {
    if (index >= keys_.size())
        throw std::out_of_range("no key " + std::to_string(index) + " (the path has " + std::to_string(keys_.size()) +
                                " keys)");
    std::vector<CameraKey> keys = keys_;
    keys[index] = key;
    setKeys(std::move(keys));
}

void CameraPath::rebuild() {
    count_ = keys_.size();
    time_.clear();
    point_.clear();
    knot_.clear();
    tangent_.clear();
    knotRate_.clear();
    turnTime_.clear();
    rotation_.clear();
    controlAfter_.clear();
    controlBefore_.clear();
    fov_.clear();
    fovRate_.clear();
    tablePlayback_.clear();
    tableKeyed_.clear();
    if (count_ == 0) return;

    // A loop whose last key repeats the first closes there: drop the repeat from the spline.
    const bool closesAtLastKey = options_.loop && count_ >= 2 && sameKey(keys_.front(), keys_.back());
    if (closesAtLastKey) --count_;
    const std::size_t n = count_;

    for (std::size_t i = 0; i < n; ++i) {
        time_.push_back(keys_[i].time);
        point_.emplace_back(keys_[i].position);
        fov_.push_back(keys_[i].yfov);
        glm::dquat q = glm::normalize(glm::dquat(keys_[i].rotation));
        if (i > 0 && glm::dot(rotation_.back(), q) < 0.0) q = -q;  // shorter arc from the previous key
        rotation_.push_back(q);
    }
    if (n == 1) {
        // Still camera (also a loop closing on its only key): the loop lasts until the repeat.
        if (closesAtLastKey) time_.push_back(keys_.back().time);
        return;
    }

    const bool loop = options_.loop;
    const std::size_t segments = loop ? n : n - 1;
    if (loop) {
        const double first = time_.front(), last = time_.back();
        time_.push_back(closesAtLastKey ? static_cast<double>(keys_.back().time)
                                        : last + (last - first) / static_cast<double>(n - 1));
    }
    const auto keyAfter = [n](std::size_t segment) { return (segment + 1) % n; };

    std::vector<double> width(segments), knotStep(segments), knotSlope(segments);
    knot_.push_back(0.0);
    for (std::size_t j = 0; j < segments; ++j) {
        width[j] = time_[j + 1] - time_[j];
        // Centripetal parameterization: knot steps grow with the square root of the chord.
        knotStep[j] = std::max(std::sqrt(glm::length(point_[keyAfter(j)] - point_[j])), kMinKnotStep);
        knot_.push_back(knot_.back() + knotStep[j]);
        knotSlope[j] = knotStep[j] / width[j];
    }
    knotRate_ = pchipRates(width, knotSlope, loop);

    // Position: the derivative of the non-uniform Catmull-Rom curve in its knot parameter at each
    // key (Barry–Goldman's pyramid differentiated there); open ends take the chord.
    tangent_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool hasPrev = loop || i > 0;
        const bool hasNext = loop || i + 1 < n;
        const std::size_t prevKey = (i + n - 1) % n;
        const std::size_t nextKey = (i + 1) % n;
        if (hasPrev && hasNext) {
            const double a = knotStep[(i + segments - 1) % segments], b = knotStep[i % segments];
            tangent_[i] = (point_[i] - point_[prevKey]) / a - (point_[nextKey] - point_[prevKey]) / (a + b) +
                          (point_[nextKey] - point_[i]) / b;
        } else if (hasNext) {
            tangent_[i] = (point_[nextKey] - point_[i]) / knotStep[i];
        } else {
            tangent_[i] = (point_[i] - point_[prevKey]) / knotStep[segments - 1];
        }
    }

    // Rotation and fov run on their own timeline: the key times, or with constant speed the
    // playback times at which the camera passes each key's position. Splining them there (rather
    // than mapping playback time through the arc-length table) keeps them C1 and keeps turns
    // bounded where the position slows down near a still key.
    turnTime_ = time_;
    if (options_.constantSpeed) buildArcLengthTable(width);
    if (!tablePlayback_.empty())
        for (std::size_t j = 0; j <= segments; ++j)
            turnTime_[j] = tablePlayback_[j * static_cast<std::size_t>(kCellsPerSegment)];

    std::vector<double> turnWidth(segments), fovSlope(segments);
    for (std::size_t j = 0; j < segments; ++j) {
        turnWidth[j] = turnTime_[j + 1] - turnTime_[j];
        fovSlope[j] = (fov_[keyAfter(j)] - fov_[j]) / turnWidth[j];
    }
    fovRate_ = pchipRates(turnWidth, fovSlope, loop);

    // Rotation: angular velocity at each key (body frame, rad/s) as the time-weighted
    // Catmull-Rom average of the neighbouring segments' angular velocities, then Bézier control
    // points a third of a segment along it on either side, which makes the spline C1 at the key.
    controlAfter_.resize(n);
    controlBefore_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool hasPrev = loop || i > 0;
        const bool hasNext = loop || i + 1 < n;
        const std::size_t prevSegment = (i + segments - 1) % segments;  // ends at key i
        const std::size_t nextSegment = i % segments;                   // starts at key i
        const std::size_t prevKey = (i + n - 1) % n;
        const std::size_t nextKey = (i + 1) % n;
        glm::dvec3 toNext(0.0), fromPrev(0.0);
        if (hasNext)
            toNext = rotationVector(glm::conjugate(rotation_[i]) * rotation_[nextKey]) / turnWidth[nextSegment];
        if (hasPrev)
            fromPrev = rotationVector(glm::conjugate(rotation_[prevKey]) * rotation_[i]) / turnWidth[prevSegment];
        glm::dvec3 omega = hasNext ? toNext : fromPrev;
        if (hasPrev && hasNext) {
            const double hp = turnWidth[prevSegment], hn = turnWidth[nextSegment];
            omega = (hn * fromPrev + hp * toNext) / (hp + hn);
        }
        controlAfter_[i] =
            hasNext ? rotation_[i] * fromRotationVector(omega * (turnWidth[nextSegment] / 3.0)) : rotation_[i];
        controlBefore_[i] =
            hasPrev ? rotation_[i] * fromRotationVector(-omega * (turnWidth[prevSegment] / 3.0)) : rotation_[i];
    }
}

void CameraPath::buildArcLengthTable(const std::vector<double>& width) {
    // Positions at kCellsPerSegment steps of keyed time per segment; playback time then advances
    // by chord / speed in moving segments and by keyed time in still ones.
    const std::size_t segments = width.size();
    std::vector<std::vector<double>> chords(segments);
    std::vector<double> segmentLength(segments, 0.0);
    double total = 0.0;
    for (std::size_t j = 0; j < segments; ++j) {
        glm::dvec3 previous = point_[j];
        for (int c = 1; c <= kCellsPerSegment; ++c) {
            const glm::dvec3 p = positionAt(j, time_[j] + width[j] * c / kCellsPerSegment);
            chords[j].push_back(glm::length(p - previous));
            segmentLength[j] += chords[j].back();
            previous = p;
        }
        total += segmentLength[j];
    }
    if (!(total > 0.0)) return;  // the camera never moves: keyed timing is all there is
    double movingTime = 0.0;
    for (std::size_t j = 0; j < segments; ++j)
        if (segmentLength[j] > kStillFraction * total) movingTime += width[j];
    const double speed = total / movingTime;  // metres per second

    double playback = time_.front();
    tablePlayback_.push_back(playback);
    tableKeyed_.push_back(time_.front());
    for (std::size_t j = 0; j < segments; ++j) {
        const bool moving = segmentLength[j] > kStillFraction * total;
        for (int c = 1; c <= kCellsPerSegment; ++c) {
            playback += moving ? chords[j][static_cast<std::size_t>(c - 1)] / speed : width[j] / kCellsPerSegment;
            tablePlayback_.push_back(playback);
            tableKeyed_.push_back(time_[j] + width[j] * c / kCellsPerSegment);
        }
    }
    // Rounding aside, playback ends where the keyed timeline does; make it exact.
    tablePlayback_.back() = time_.back();
    tableKeyed_.back() = time_.back();
}

float CameraPath::startTime() const { return keys_.empty() ? 0.0f : keys_.front().time; }

float CameraPath::endTime() const { return keys_.empty() ? 0.0f : static_cast<float>(time_.back()); }

glm::dvec3 CameraPath::positionAt(std::size_t j, double u) const {
    const std::size_t next = (j + 1) % count_;
    const double width = time_[j + 1] - time_[j];
    const double s = std::clamp((u - time_[j]) / width, 0.0, 1.0);
    const double step = knot_[j + 1] - knot_[j];
    const double knot = hermite(knot_[j], knot_[j + 1], knotRate_[j] * width, knotRate_[j + 1] * width, s);
    const double w = std::clamp((knot - knot_[j]) / step, 0.0, 1.0);
    return hermite(point_[j], point_[next], tangent_[j] * step, tangent_[next] * step, w);
}

double CameraPath::playbackTime(double t) const {
    const double start = time_.front(), end = time_.back();
    const double length = end - start;
    if (options_.loop) {
        double x = std::fmod(t - start, length);
        if (x < 0.0) x += length;
        return start + x;
    }
    const double clamped = std::clamp(t, start, end);
    if (!options_.easeInOut) return clamped;
    const double ramp = std::min(static_cast<double>(kEaseSeconds) / length, 0.25);
    return start + length * easeInOut((clamped - start) / length, ramp);
}

double CameraPath::keyedTime(double playback) const {
    if (tablePlayback_.empty()) return playback;
    const std::size_t i = std::min(segmentIn(tablePlayback_, playback), tablePlayback_.size() - 2);
    const double span = tablePlayback_[i + 1] - tablePlayback_[i];
    const double f = span > 0.0 ? std::clamp((playback - tablePlayback_[i]) / span, 0.0, 1.0) : 0.0;
    return tableKeyed_[i] + f * (tableKeyed_[i + 1] - tableKeyed_[i]);
}

std::optional<CameraPose> CameraPath::evaluate(double t) const {
    if (keys_.empty()) return std::nullopt;
    if (count_ == 1) {
        const CameraKey& key = keys_.front();
        return CameraPose{key.position, key.rotation, key.yfov};
    }
    const double playback = playbackTime(t);
    const double keyed = keyedTime(playback);

    const std::size_t j = segmentIn(turnTime_, playback);
    const std::size_t next = (j + 1) % count_;
    const double width = turnTime_[j + 1] - turnTime_[j];
    const double s = std::clamp((playback - turnTime_[j]) / width, 0.0, 1.0);
    // Spherical Bézier by De Casteljau's construction with slerp.
    const glm::dquat& b0 = rotation_[j];
    const glm::dquat& b1 = controlAfter_[j];
    const glm::dquat& b2 = controlBefore_[next];
    const glm::dquat& b3 = rotation_[next];
    const glm::dquat c01 = slerpShort(b0, b1, s), c12 = slerpShort(b1, b2, s), c23 = slerpShort(b2, b3, s);
    const glm::dquat rotation = slerpShort(slerpShort(c01, c12, s), slerpShort(c12, c23, s), s);
    const double fov = hermite(fov_[j], fov_[next], fovRate_[j] * width, fovRate_[next] * width, s);

    CameraPose pose;
    pose.position = glm::vec3(positionAt(segmentIn(time_, keyed), keyed));
    pose.rotation = glm::quat(glm::normalize(rotation));
    pose.yfov = static_cast<float>(fov);
    return pose;
}

std::optional<CameraView> CameraPath::view(double t, float aspect, float znear, float zfar) const {
    const std::optional<CameraPose> pose = evaluate(t);
    if (!pose) return std::nullopt;
    return makeCameraView(pose->world(), pose->yfov, aspect, znear, zfar);
}

std::optional<CameraView> CameraPath::view(double t, float aspect, const Aabb& sceneBounds) const {
    const std::optional<CameraPose> pose = evaluate(t);
    if (!pose) return std::nullopt;
    // The same fit as sceneCameraView for a camera that leaves zfar open: near as far out as the
    // scene's bounding sphere allows (depth precision), far just behind the sphere.
    float znear = 0.05f;  // metres
    float zfar = 1000.0f;
    if (!sceneBounds.empty()) {
        const float radius = std::max(sceneBounds.radius(), 1e-3f);
        const float distance = glm::length(sceneBounds.center() - pose->position);
        znear = std::max(znear, 1e-3f * radius);
        if (distance > radius) znear = std::max(znear, 0.5f * (distance - radius));
        zfar = std::max(1.01f * (distance + radius), 2.0f * znear);
    }
    return makeCameraView(pose->world(), pose->yfov, aspect, znear, zfar);
}

std::vector<double> CameraPath::frameTimes(double fps) const {
    if (!std::isfinite(fps) || !(fps > 0.0))
        throw std::invalid_argument("frames per second must be a positive number, got " + number(fps));
    if (keys_.empty()) return {};
    const double start = startTime();
    const double length = static_cast<double>(endTime()) - start;
    if (!(length > 0.0)) return {start};
    // A whole number of frames up to rounding (90 frames at 30 fps for 3 s) counts as whole.
    const double frames = length * fps;
    const double count =
        options_.loop && count_ > 1 ? std::max(1.0, std::ceil(frames - 1e-6)) : std::floor(frames + 1e-6) + 1.0;
    if (count > static_cast<double>(kMaxFrames))
        throw std::invalid_argument("the path is " + number(length) + " s long: at " + number(fps) + " fps that is " +
                                    number(count) + " frames, more than " + std::to_string(kMaxFrames));
    std::vector<double> times(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < times.size(); ++i) times[i] = start + static_cast<double>(i) / fps;
    return times;
}

}  // namespace lit
