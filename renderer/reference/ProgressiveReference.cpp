#include "reference/ProgressiveReference.h"

#include "Log.h"
#include "scene/Sky.h"

#include <algorithm>
#include <chrono>

namespace lit::reference {

ProgressiveReference::ProgressiveReference(int maxSamples) : maxSamples_(std::max(1, maxSamples)) {
    worker_ = std::thread([this] { run(); });
}

ProgressiveReference::~ProgressiveReference() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
        cancel_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

void ProgressiveReference::update(const Scene& scene, const CameraView& camera, int width, int height,
                                  const ReferenceSettings& settings, const RenderSettings* lighting) {
    Key key;
    key.geometry = scene.geometryRevision;
    key.material = scene.materialRevision;
    key.light = scene.lightRevision;
    key.sceneAddress = &scene;
    key.nodeCount = scene.nodes.size();
    key.view = camera.view;
    key.projection = camera.projection;
    key.width = width;
    key.height = height;
    key.bounces = settings.bounces;
    key.seed = settings.seed;
    if (lighting) {
        key.lighting = {true, lighting->sky};
    }
    {
        std::lock_guard lock(mutex_);
        if (haveKey_ && key == key_) return;
        haveKey_ = true;
        key_ = key;
        auto job = std::make_unique<Job>();
        job->scene = scene;  // the worker traces its own copy: the caller keeps editing its scene
        job->camera = camera;
        job->width = width;
        job->height = height;
        job->settings = settings;
        if (lighting) job->lighting = *lighting;
        pending_ = std::move(job);
        cancel_ = true;  // the running job (if any) stops after the tiles in flight
    }
    wake_.notify_all();
}

void ProgressiveReference::stop() {
    std::lock_guard lock(mutex_);
    pending_.reset();
    haveKey_ = false;  // the next update() starts a job again
    cancel_ = true;
}

bool ProgressiveReference::latest(View view, const RenderSettings& terms, std::vector<float>& rgb, int& width,
                                  int& height) const {
    std::lock_guard lock(mutex_);
    if (!havePublished_) return false;
    rgb = published_.viewRgb(view, terms);
    width = published_.width;
    height = published_.height;
    return true;
}

ProgressiveStatus ProgressiveReference::status() const {
    std::lock_guard lock(mutex_);
    return status_;
}

void ProgressiveReference::run() {
    using Clock = std::chrono::steady_clock;
    Log quiet;  // LightSetup's warnings were already shown by the rasterizer
    quiet.setSink(nullptr);
    for (;;) {
        std::unique_ptr<Job> job;
        {
            std::unique_lock lock(mutex_);
            status_.running = false;
            wake_.wait(lock, [this] { return quit_ || pending_; });
            if (quit_) return;
            job = std::move(pending_);
            cancel_ = false;
            havePublished_ = false;
            status_ = ProgressiveStatus{0, 0.0, 0.0, true, status_.restarts + 1};
        }
        try {
            job->scene.updateWorldTransforms();
            if (job->lighting) {
                // The sky first: with the default sun in, an Auto sky would see a lit scene. An
                // unreadable .hdr gives the gradient, as in the rasterizer (which reports it).
                job->settings.environment = makeSkyFunction(job->scene, *job->lighting);
                addDefaultSun(job->scene, *job->lighting);
            }
            const ReferenceScene scene(job->scene, quiet);
            PathTracer tracer(scene, job->camera, job->width, job->height, job->settings);
            const Clock::time_point start = Clock::now();
            while (tracer.samplesDone() < maxSamples_) {
                if (!tracer.addSamples(1, &cancel_)) break;
                const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
                std::lock_guard lock(mutex_);
                if (cancel_) break;
                published_ = tracer.image();
                havePublished_ = true;
                status_.samplesPerPixel = tracer.samplesDone();
                const double paths = static_cast<double>(tracer.samplesDone()) * job->width * job->height;
                status_.samplesPerSecond = seconds > 0.0 ? paths / seconds : 0.0;
                status_.raysPerSecond = seconds > 0.0 ? static_cast<double>(tracer.raysTraced()) / seconds : 0.0;
            }
        } catch (const std::exception&) {
            // A scene Embree cannot take (or a zero size) leaves the view without an image; the next
            // edit starts a new job.
        }
    }
}

}  // namespace lit::reference
