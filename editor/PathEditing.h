#pragma once
// Camera path editing for the timeline panel and the script's key/play/time commands:
// each action is one undo step on the Document, and playback state lives beside it.
// Window-free (lit_editor_core), so the tests drive it directly.

#include <optional>
#include <string>

#include "Document.h"
#include "animation/CameraPath.h"
#include "scene/CameraView.h"

namespace lit::editor {

// Keys closer than this in time are one key: adding at an occupied time moves the new key on.
inline constexpr float kMinKeySpacing = 1.0f / 120.0f;  // seconds
// The gap "+ Key" leaves after the last key of a path with fewer than two intervals to learn
// from (Blender's and Unity's keying moves on by a frame step; a second reads as a camera move).
inline constexpr float kDefaultKeyInterval = 1.0f;  // seconds
// The shortest gap "+ Key" takes from a path's mean spacing: keys piled up closer than this
// would give a path too fast to see.
inline constexpr float kMinAddedKeyInterval = 0.1f;  // seconds

struct PathPlayback;  // below

// The key a fly camera gives: its position, orientation and field of view at `time`.
CameraKey keyFromCamera(const FlyCamera& camera, float time);
// Points a fly camera the way a path pose looks (yaw/pitch from the rotation; roll is dropped,
// the fly camera has none).
void applyPoseToCamera(const CameraPose& pose, FlyCamera& camera);
// Puts the fly camera where the path is at `time`; nothing for an empty path.
void lookThroughPath(const CameraPath& path, double time, FlyCamera& camera);

// Adds `key` as one undo step ("Add Key"); when its time is taken it goes kMinKeySpacing after
// the last key at or after it. Selects it and returns its index.
std::size_t addKey(Document& doc, CameraKey key);
// Where "+ Key" puts a key with the playhead at `playhead` (seconds):
// - an empty path: at the playhead;
// - the playhead past the last key, or between two keys (not on one): at the playhead, as a
//   keyframe inserted at the current frame in Blender;
// - the playhead on a key (within kMinKeySpacing) or before the first key: after the last key,
//   by kDefaultKeyInterval when the path has one key, else by its mean key spacing (at least
//   kMinAddedKeyInterval). So "fly to a view, + Key" repeated gives keys a second apart.
float nextKeyTime(const CameraPath& path, double playhead);
// The timeline's "+ Key" and the script's "key add": a key from `camera` at nextKeyTime, one
// undo step; the playhead moves to it. Returns its index.
std::size_t addKeyFromView(Document& doc, PathPlayback& playback, const FlyCamera& camera);
// The seconds the ruler shows and the playhead can be scrubbed over: from the earlier of 0 and
// the first key to past the end of playSpan by a quarter of it (at least kDefaultKeyInterval),
// so there is room to scrub beyond the end and add a key there. `animationEnd` is the scene's
// node animations' last key (animation/NodeAnimation.h; 0: none).
struct TimeSpan {
    double start = 0.0, end = kDefaultKeyInterval;
};
TimeSpan scrubSpan(const CameraPath& path, double animationEnd = 0.0);
// The seconds playback runs over, one clock for the camera path and the node animations: the
// path's keys, joined with 0 s .. animationEnd when the scene has node animations (they start at
// 0 s). {0, 0} when there is neither.
TimeSpan playSpan(const CameraPath& path, double animationEnd = 0.0);
// Whether there is anything to play: keys, or node animations.
inline bool hasTimeline(const CameraPath& path, double animationEnd) { return !path.empty() || animationEnd > 0.0; }
// The path's duration (last key − first key) made `seconds` by scaling every key's time about
// the first key; the spacing stays at least kMinKeySpacing. Not an undo step by itself (a drag
// of the Duration field is one). False with fewer than two keys or a duration that is not > 0.
bool scalePathDuration(Document& doc, float seconds);
// The same as one undo step ("Path Duration"), for the script.
bool setPathDuration(Document& doc, float seconds);
// The key whose diamond is nearest `time` within `tolerance` seconds (the ruler's pick: of
// keys drawn on top of each other the nearest wins, not the last drawn), or -1.
int keyNear(const CameraPath& path, double time, double tolerance);

// Deletes key `index` ("Delete Key"); the selection moves to a neighbour. Returns false (and
// changes nothing) for an index out of range.
bool deleteKey(Document& doc, std::size_t index);
// The time key `index` may be given: strictly between its neighbours (by kMinKeySpacing).
float clampKeyTime(const CameraPath& path, std::size_t index, float time);
// Sets key `index`'s values, clamping its time as above. Not an undo step by itself: the
// caller brackets it (a drag is one step). Returns false for an index out of range.
bool setKeyValues(Document& doc, std::size_t index, CameraKey key);
// One-shot forms with their own undo step.
bool retimeKey(Document& doc, std::size_t index, float time);                  // "Retime Key"
bool updateKeyFromCamera(Document& doc, std::size_t index, const FlyCamera& camera);  // "Update Key"
// Path options as one undo step ("Path Options").
void setPathOptions(Document& doc, const CameraPathOptions& options);

// Where the playhead is and whether it moves, over playSpan: the camera path and the scene's node
// animations on one clock. The path's own `loop` option decides whether the playhead wraps at
// the end; without it playback stops at the end.
// Playback rates the timeline's Speed slider and the script's "play SPEED" take.
inline constexpr float kMinPlaybackSpeed = 0.1f;
inline constexpr float kMaxPlaybackSpeed = 4.0f;

struct PathPlayback {
    double time = 0.0;    // seconds, in the path's time
    bool playing = false;
    float speed = 1.0f;   // playback rate
    bool lookThrough = true;  // the viewport looks through the path camera while playing/scrubbing

    // Advances by dtSeconds × speed when playing; wraps (loop) or stops at the end of
    // playSpan(path, animationEnd).
    void advance(const CameraPath& path, double dtSeconds, double animationEnd = 0.0);
    // Starts playing; from the start when the playhead is at (or past) the end of an open
    // timeline, or before its start. Nothing without keys or node animations.
    void play(const CameraPath& path, double animationEnd = 0.0);
};

// Applies one script command of the timeline family (key add|delete|select I|time I T|update I,
// play [SPEED], pause, time T, duration T) to the document, playback and fly camera. Returns ""
// or an error message. "play" plays the camera path and the scene's node animations together
// (either alone when the scene has only one); "time T" moves the playhead, which poses the
// animated nodes at T from the next frame (the App applies them every frame). "key add" is the timeline's "+ Key" (addKeyFromView); "key select I"
// moves the playhead to the key and, like clicking it, points the camera there.
std::string runPathCommand(Document& doc, PathPlayback& playback, FlyCamera& camera, const std::string& name,
                           const std::vector<std::string>& args);

}  // namespace lit::editor
