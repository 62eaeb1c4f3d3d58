#pragma once
// A GL 4.5 core context without a window or X server, through EGL: the surfaceless Mesa
// platform first, then the device platform. Rendering goes into the renderer's own framebuffers.

#include <memory>
#include <string>

namespace lit {

class HeadlessContext {
public:
    // Throws std::runtime_error with a clear message when no GL 4.5 core context can be made.
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    std::string description() const;  // "EGL surfaceless: 4.5 (Core Profile) Mesa ... llvmpipe"

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace lit
