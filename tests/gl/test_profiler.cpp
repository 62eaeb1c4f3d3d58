// Profiler::poll: the editor shows its last image again when nothing changed and renders no frame,
// so the last rendered frame's timings must arrive without a later beginFrame.
#include <epoxy/gl.h>

#include "GlTestSupport.h"
#include "Profiler.h"

namespace lit::test {
namespace {

using ProfilerPoll = ContextFixture;

TEST_F(ProfilerPoll, CollectsTheLastFrameWithoutStartingAnother) {
    Profiler profiler;
    profiler.beginFrame();
    {
        Profiler::Scope scope(profiler, "clear");
        glClear(GL_COLOR_BUFFER_BIT);
    }
    profiler.endFrame();
    EXPECT_TRUE(profiler.timings().empty());  // read back kFramesInFlight frames later as a rule
    glFinish();
    profiler.poll();
    EXPECT_EQ(profiler.completedFrames(), 1u);
    ASSERT_EQ(profiler.timings().size(), 1u);
    EXPECT_EQ(profiler.timings()[0].name, "clear");
    EXPECT_TRUE(profiler.timings()[0].ran);
    EXPECT_EQ(profiler.timings()[0].frame, 1u);
    // Nothing more to collect: the timings stay those of the last frame.
    profiler.poll();
    EXPECT_EQ(profiler.completedFrames(), 1u);
    EXPECT_EQ(profiler.timings()[0].frame, 1u);
}

}  // namespace
}  // namespace lit::test
