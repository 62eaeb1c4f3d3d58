#pragma once
// The reference path tracer run progressively on a background thread, for interactive views
// (the editor's Reference and Difference views): samples accumulate while the scene, the camera,
// the image size and the reference settings stay the same, and start over as soon as any of them
// changes. No GL: the caller uploads the image it gets from latest().

#include "reference/PathTracer.h"
#include "scene/Scene.h"

#include "RenderSettings.h"

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace lit::reference {

struct ProgressiveStatus {
    int samplesPerPixel = 0;       // completed by every pixel of the current image
    double samplesPerSecond = 0.0;  // camera paths per second since the last restart
    double raysPerSecond = 0.0;
    bool running = false;          // the worker is tracing (false when idle at maxSamples or stopped)
    std::uint64_t restarts = 0;    // accumulations started so far
};

class ProgressiveReference {
public:
    // `maxSamples`: the worker rests once every pixel has this many samples.
    explicit ProgressiveReference(int maxSamples = 4096);
    ~ProgressiveReference();  // stops and joins the worker
    ProgressiveReference(const ProgressiveReference&) = delete;
    ProgressiveReference& operator=(const ProgressiveReference&) = delete;

    // Call whenever the view may have changed (e.g. every frame). Restarts the accumulation when
    // the scene's revisions (geometry, material, light), the camera's matrices, the size or the
    // settings' bounces/seed differ from the running job; the scene is copied then, so the caller
    // may edit its own afterwards. Cheap when nothing changed.
    // `lighting`: the render settings whose sky and default sun the reference shares with the
    // rasterizer (scene/Sky.h), as lit-render --reference does: rays that leave the scene see
    // makeSkyFunction(scene, *lighting) (replacing settings.environment), and a scene without
    // lights gets the default sun. A change of those settings restarts too. Null: neither.
    void update(const Scene& scene, const CameraView& camera, int width, int height, const ReferenceSettings& settings,
                const RenderSettings* lighting = nullptr);

    // Linear RGB of `view` (bottom-up rows, settings' term switches for Final) from the latest
    // completed pass; false (and `rgb` untouched) before the first pass of the current job.
    bool latest(View view, const RenderSettings& terms, std::vector<float>& rgb, int& width, int& height) const;
    ProgressiveStatus status() const;

    // Stops tracing (the last image stays available). update() starts again.
    void stop();

private:
    struct Job {
        Scene scene;
        CameraView camera;
        int width = 0, height = 0;
        ReferenceSettings settings;
        std::optional<RenderSettings> lighting;
    };
    // The RenderSettings the sky and the default sun depend on.
    struct LightingKey {
        bool given = false;
        SkySettings sky;
        bool operator==(const LightingKey&) const = default;
    };
    struct Key {
        std::uint64_t geometry = 0, material = 0, light = 0;
        const void* sceneAddress = nullptr;
        std::size_t nodeCount = 0;
        glm::mat4 view{1.0f}, projection{1.0f};
        int width = 0, height = 0, bounces = 0;
        std::uint64_t seed = 0;
        LightingKey lighting;
        bool operator==(const Key&) const = default;
    };
    void run();

    const int maxSamples_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::unique_ptr<Job> pending_;       // the job the worker picks up next
    bool haveKey_ = false;
    Key key_;                            // of the newest job given to update()
    std::atomic<bool> cancel_{false};    // the running job must stop (restart or shutdown)
    bool quit_ = false;
    ReferenceImage published_;           // the latest completed pass of the current job
    bool havePublished_ = false;
    ProgressiveStatus status_;
    std::thread worker_;
};

}  // namespace lit::reference
