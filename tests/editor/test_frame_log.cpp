#include <gtest/gtest.h>

#include "FrameLog.h"

namespace {

using namespace lit::editor;

TEST(FrameLog, EachFrameLastsUntilTheNextBegins) {
    FrameLog log;
    log.add({10.0, 1.0f, {640, 360}, false});
    log.last().rendered = true;
    log.add({10.25, 0.5f, {320, 180}, true});
    log.last().refinedVoxels = 4096;
    log.last().rendered = true;
    log.add({10.75, 0.5f, {320, 180}, false});  // the last image shown again (rendered = false)
    log.last().playhead = 1.5;
    log.last().playing = true;
    log.last().camera = {1.0f, -2.0f, 0.25f};
    log.last().selectedNode = 7;
    log.add({10.76, 0.5f, {320, 180}, false});  // the GI advanced alone
    log.last().refinedVoxels = 2048;
    log.last().giOnly = true;
    log.last().giUpdateDone = 0.25f;
    EXPECT_EQ(log.csv(10.80),
              "frame,start_s,duration_ms,render_width,render_height,render_scale,camera_moved,refined_voxels,rendered,"
              "playhead_s,playing,camera_x,camera_y,camera_z,selected_node,gi_only,gi_update_done\n"
              "0,0.0000,250.00,640,360,1.00,0,0,1,0.0000,0,0.0000,0.0000,0.0000,-1,0,1.000\n"
              "1,0.2500,500.00,320,180,0.50,1,4096,1,0.0000,0,0.0000,0.0000,0.0000,-1,0,1.000\n"
              "2,0.7500,10.00,320,180,0.50,0,0,0,1.5000,1,1.0000,-2.0000,0.2500,7,0,1.000\n"
              "3,0.7600,40.00,320,180,0.50,0,2048,0,0.0000,0,0.0000,0.0000,0.0000,-1,1,0.250\n");
}

TEST(FrameLog, AnEmptyLogIsTheHeader) {
    EXPECT_EQ(
        FrameLog().csv(1.0),
        "frame,start_s,duration_ms,render_width,render_height,render_scale,camera_moved,refined_voxels,rendered,"
        "playhead_s,playing,camera_x,camera_y,camera_z,selected_node,gi_only,gi_update_done\n");
}

}  // namespace
