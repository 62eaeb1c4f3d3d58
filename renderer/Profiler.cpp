#include "Profiler.h"

#include <epoxy/gl.h>

#include <cstring>

namespace lit {

namespace {
gl::QueryHandle makeTimestampQuery(std::vector<gl::QueryHandle>& pool) {
    if (!pool.empty()) {
        gl::QueryHandle q = std::move(pool.back());
        pool.pop_back();
        return q;
    }
    GLuint n = 0;
    glCreateQueries(GL_TIMESTAMP, 1, &n);
    return gl::QueryHandle(n);
}
double msSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

Profiler::Profiler() { frameStart_ = std::chrono::steady_clock::now(); }

int Profiler::passIndex(const char* name) {
    for (std::size_t i = 0; i < passNames_.size(); ++i)
        if (passNames_[i] == name) return static_cast<int>(i);
    passNames_.emplace_back(name);
    return static_cast<int>(passNames_.size() - 1);
}

Profiler::Scope::Scope(Profiler& profiler, const char* name)
    : profiler_(profiler), start_(std::chrono::steady_clock::now()) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(std::strlen(name)), name);
    Frame& frame = profiler_.frames_[static_cast<std::size_t>(profiler_.current_)];
    Sample sample{profiler_.passIndex(name), makeTimestampQuery(profiler_.pool_), {}, 0.0};
    glQueryCounter(sample.begin.id(), GL_TIMESTAMP);
    frame.samples.push_back(std::move(sample));
    slot_ = static_cast<int>(frame.samples.size() - 1);
}

Profiler::Scope::~Scope() {
    Frame& frame = profiler_.frames_[static_cast<std::size_t>(profiler_.current_)];
    Sample& sample = frame.samples[static_cast<std::size_t>(slot_)];
    sample.end = makeTimestampQuery(profiler_.pool_);
    glQueryCounter(sample.end.id(), GL_TIMESTAMP);
    sample.cpuMs = msSince(start_);
    glPopDebugGroup();
}

bool Profiler::collect(Frame& frame, bool wait) {
    if (!frame.pending) return false;
    if (!wait) {
        for (const Sample& s : frame.samples) {
            GLint available = 0;
            glGetQueryObjectiv(s.end.id(), GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) return false;
        }
    }
    std::vector<PassTiming> timings(passNames_.size());
    for (std::size_t i = 0; i < passNames_.size(); ++i) {
        timings[i].name = passNames_[i];
        timings[i].frame = frame.number;
    }
    for (Sample& s : frame.samples) {
        GLuint64 t0 = 0, t1 = 0;
        glGetQueryObjectui64v(s.begin.id(), GL_QUERY_RESULT, &t0);
        glGetQueryObjectui64v(s.end.id(), GL_QUERY_RESULT, &t1);
        PassTiming& t = timings[static_cast<std::size_t>(s.passIndex)];
        t.gpuMs += static_cast<double>(t1 - t0) * 1e-6;
        t.cpuMs += s.cpuMs;
        t.ran = true;
        pool_.push_back(std::move(s.begin));
        pool_.push_back(std::move(s.end));
    }
    frame.samples.clear();
    frame.pending = false;
    lastRun_.resize(timings.size());
    for (std::size_t i = 0; i < timings.size(); ++i)
        if (timings[i].ran) lastRun_[i] = timings[i];
    latest_ = std::move(timings);
    recent_.push_back(latest_);
    if (recent_.size() > static_cast<std::size_t>(kFramesInFlight)) recent_.pop_front();
    ++completedFrames_;
    return true;
}

void Profiler::beginFrame() {
    frameStart_ = std::chrono::steady_clock::now();
    ++frameNumber_;
    // Slot current_ was filled kFramesInFlight frames ago and is about to be reused: collect it
    // even if that means waiting (the GPU is that far behind). Then collect younger frames that
    // are already finished, oldest first, so `latest_` ends on the newest one.
    collect(frames_[static_cast<std::size_t>(current_)], true);
    for (int i = 1; i < kFramesInFlight; ++i) {
        Frame& frame = frames_[static_cast<std::size_t>((current_ + i) % kFramesInFlight)];
        if (frame.pending && !collect(frame, false)) break;
    }
}

void Profiler::endFrame() {
    frames_[static_cast<std::size_t>(current_)].pending = true;
    frames_[static_cast<std::size_t>(current_)].number = frameNumber_;
    current_ = (current_ + 1) % kFramesInFlight;
    lastCpuFrameMs_ = msSince(frameStart_);
}

void Profiler::flush() {
    for (int i = 0; i < kFramesInFlight; ++i)
        collect(frames_[static_cast<std::size_t>((current_ + i) % kFramesInFlight)], true);
}

void Profiler::poll() {
    for (int i = 0; i < kFramesInFlight; ++i) {
        Frame& frame = frames_[static_cast<std::size_t>((current_ + i) % kFramesInFlight)];
        if (frame.pending && !collect(frame, false)) break;
    }
}

double Profiler::gpuMs(const std::string& pass) const {
    for (const PassTiming& t : latest_)
        if (t.name == pass) return t.gpuMs;
    return 0.0;
}

const PassTiming* Profiler::lastRun(const std::string& pass) const {
    for (const PassTiming& t : lastRun_)
        if (t.name == pass && t.ran) return &t;
    return nullptr;
}

double Profiler::totalGpuMs() const {
    // Top-level passes do not nest in Lit, so their sum is the frame's GPU time.
    double sum = 0.0;
    for (const PassTiming& t : latest_) sum += t.gpuMs;
    return sum;
}

}  // namespace lit
