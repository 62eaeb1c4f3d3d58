#pragma once
// Camera paths: keyframes (time, position, orientation, vertical field of view) and the smooth
// motion through them, for fly-throughs and for benchmarking along a repeatable path. Plain
// data plus evaluation; no GL, no UI. File formats live in CameraPathIO.h.
//
// How a path moves (all in world space, conventions of docs/CONVENTIONS.md):
// - Position follows the centripetal Catmull-Rom curve through the key positions (knot spacing
//   √|ΔP|, so no cusps or self-intersections inside a segment). Plain centripetal Catmull-Rom
//   is C1 in its own knot parameter but not in time when the key times are spaced differently
//   from the knots, so the knot is driven by time through a monotone C1 cubic (Fritsch–Carlson
//   "PCHIP") through (key time, key knot). The composition is C1 in time, passes every key at
//   its time, and never runs backwards along the curve. A key where the camera stands still
//   (two keys at one position) is approached and left smoothly, with the speed going to ~0.
// - Orientation follows a spherical cubic Bézier per segment (De Casteljau with slerp, Shoemake
//   1985) whose inner control points come from a time-weighted Catmull-Rom angular velocity at
//   each key, so the angular velocity is continuous at keys (C1), unlike plain squad with
//   uneven key spacing. Every slerp takes the shorter arc: 350° → 10° of yaw turns by 20°.
// - The vertical field of view follows a monotone cubic (PCHIP) in time: smooth, and it never
//   overshoots outside the range of its neighbouring keys.
// - Options: `loop` closes the path (see CameraPath::duration()). `constantSpeed` re-times the
//   motion by arc length (a table of 256 cells per segment, built once per change) so the camera
//   moves at an even speed whatever the key spacing; orientation and fov are then splined over
//   the times at which the camera passes each key, so it still has key i's orientation where it
//   passes key i's position. A segment whose keys share a position keeps its keyed duration
//   (the camera pauses there and turns). `easeInOut` accelerates from rest and decelerates to
//   rest at the ends of an open path (constant acceleration for kEaseSeconds or a quarter of the
//   path); a loop has no ends and ignores it.
// - Cost (-O2, this machine): evaluate ≈ 0.5 µs; rebuilding after an edit ≈ 22 µs per key with
//   constantSpeed (the arc-length table), far less without: fine to rebuild on every UI edit.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/Aabb.h"
#include "scene/CameraView.h"

namespace lit {

// A path that cannot be built: the message names the key (0-based, as in the file's "keys"
// array) and the problem, e.g. "key 3: time 1.5 is not after key 2's time 2".
class CameraPathError : public std::runtime_error {
public:
    explicit CameraPathError(const std::string& message) : std::runtime_error(message) {}
};

struct CameraKey {
    float time = 0.0f;                           // seconds
    glm::vec3 position{0.0f};                    // metres, world space
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // camera to world; the camera looks down −Z
    float yfov = 0.8f;                           // vertical field of view, radians, in (0, π)

    bool operator==(const CameraKey&) const = default;
};

struct CameraPathOptions {
    bool loop = false;           // closed path: after the last key the camera flies back to the first
    bool constantSpeed = false;  // even speed along the curve instead of passing keys at their times
    bool easeInOut = false;      // start and stop at rest (open paths only; a loop has no ends)

    bool operator==(const CameraPathOptions&) const = default;
};

// Where the camera is at one instant.
struct CameraPose {
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    float yfov = 0.8f;  // radians

    glm::mat4 world() const;  // camera to world (rotation, then translation)
};

// A rotation quaternion may be this far from unit length (|len − 1|) and still be accepted (it
// is normalized); anything further is an error rather than a silent fix. Generous enough for
// values printed with 6–7 significant digits, tight enough to catch a wrong component.
inline constexpr float kQuaternionLengthTolerance = 1e-3f;

// How long the camera takes to speed up from rest at the start (and slow down at the end) with
// easeInOut: this many seconds, or a quarter of the path when that is shorter.
inline constexpr float kEaseSeconds = 1.0f;

// Checks keys as a file would give them. Throws CameraPathError naming the first bad key: a
// non-finite value, times not strictly increasing, a rotation whose length is off by more than
// kQuaternionLengthTolerance, a yfov outside (0, π).
void validateCameraKeys(const std::vector<CameraKey>& keys);

class CameraPath {
public:
    CameraPath() = default;  // no keys: "no path"
    // Validates (validateCameraKeys) and normalizes the rotations; throws CameraPathError and
    // leaves nothing built when a key is bad.
    explicit CameraPath(std::vector<CameraKey> keys, CameraPathOptions options = {});

    const std::vector<CameraKey>& keys() const { return keys_; }
    const CameraPathOptions& options() const { return options_; }
    bool empty() const { return keys_.empty(); }

    // Editing; each validates and rebuilds, and leaves the path unchanged when it throws.
    void setKeys(std::vector<CameraKey> keys);
    void setOptions(const CameraPathOptions& options);
    // Inserts `key` in time order; returns its index. Throws when a key has that time already.
    std::size_t insertKey(const CameraKey& key);
    void removeKey(std::size_t index);                     // throws std::out_of_range
    void setKey(std::size_t index, const CameraKey& key);  // must keep the times in order

    // Seconds. startTime() is the first key's time. An open path ends at the last key; a loop
    // lasts until it is back at the first key: one closing segment after the last key that takes
    // the mean key interval, or — when the last key repeats the first (same position, rotation
    // and fov) — the repeated key is taken as the closing point and the loop ends at its time.
    float startTime() const;
    float endTime() const;
    float duration() const { return endTime() - startTime(); }

    // The pose at time t (seconds). An open path clamps t to [startTime, endTime]; a loop wraps
    // t into [startTime, endTime). One key: that key for every t. No keys: std::nullopt.
    std::optional<CameraPose> evaluate(double t) const;

    // The view at time t for an output of `aspect` (width / height); near and far planes as given
    // (metres; zfar ≤ znear means an infinite far plane). std::nullopt when the path is empty.
    std::optional<CameraView> view(double t, float aspect, float znear, float zfar) const;
    // The same with near and far fitted to `sceneBounds` as seen from the camera, the way a scene
    // camera without zfar is fitted (sceneCameraView); empty bounds give 0.05 m and 1000 m.
    std::optional<CameraView> view(double t, float aspect, const Aabb& sceneBounds) const;

    // Times at which to render the path at `fps` frames per second: startTime + i / fps. An open
    // path includes its start and, when the duration is a whole number of frames, its end; a loop
    // stops one frame short of its start again. One key: one frame. Empty: none. Throws
    // std::invalid_argument unless fps is finite and positive.
    std::vector<double> frameTimes(double fps) const;

private:
    void rebuild();
    void buildArcLengthTable(const std::vector<double>& width);
    double playbackTime(double t) const;      // wrapped (loop) or clamped and eased
    double keyedTime(double playback) const;  // through the arc-length table with constantSpeed
    glm::dvec3 positionAt(std::size_t segment, double keyed) const;

    std::vector<CameraKey> keys_;
    CameraPathOptions options_;

    // Built by rebuild() from keys_ and options_ (double precision: the spline and the arc-length
    // table difference nearby values). Key j of the spline is keys_[j]; for a loop whose last key
    // repeats the first, that last key is dropped here and time_.back() is its time.
    std::size_t count_ = 0;            // keys in the spline
    std::vector<double> time_;         // key times: segment boundaries, segments + 1 values (seconds)
    std::vector<glm::dvec3> point_;    // key positions
    std::vector<double> knot_;         // centripetal knot at each boundary (√metres)
    std::vector<glm::dvec3> tangent_;  // dP/dknot at each key
    std::vector<double> knotRate_;     // dknot/dt at each boundary
    // Boundaries of the rotation and fov splines in playback time (seconds): time_, or with
    // constantSpeed the times at which the camera passes the keys.
    std::vector<double> turnTime_;
    std::vector<glm::dquat> rotation_;       // key rotations, normalized, consecutive dot ≥ 0
    std::vector<glm::dquat> controlAfter_;   // Bézier control point after each key
    std::vector<glm::dquat> controlBefore_;  // Bézier control point before each key
    std::vector<double> fov_;                // key fovs (radians)
    std::vector<double> fovRate_;            // dfov/dt at each boundary (radians per second)
    // Constant speed: keyed time at increasing playback times (empty = play by key times).
    std::vector<double> tablePlayback_;
    std::vector<double> tableKeyed_;
};

}  // namespace lit
