#pragma once
// Editor-only state that the panels edit besides the Scene and the RenderSettings: which
// panels are shown and how the viewport is presented. None of it reaches the renderer.

namespace lit::editor {

struct PanelVisibility {
    bool stats = true;
    bool renderSettings = true;
    bool camera = true;
    bool log = true;
};

struct ViewportSettings {
    // Render resolution as a fraction of the window's framebuffer; the output is stretched
    // (bilinear) to the window. Below 1 keeps the editor responsive on slow GPUs and llvmpipe,
    // where cone tracing costs scale with the pixel count.
    float renderScale = 1.0f;
};

}  // namespace lit::editor
