#pragma once
// lit-render --reference --node-map FILE.txt: which scene node each pixel sees, from the reference's
// first hit at the pixel's centre, for per-surface comparisons (tools/room_accuracy.py --nodes).
// Text:
//   lit-node-map 1
//   WIDTH HEIGHT
//   nodes N            then N lines "INDEX NAME" (the name to the end of the line)
//   pixels             then HEIGHT rows, top row first, of WIDTH tokens: the node index (-1: nothing),
//                      with "*" appended where a punctual light reaches the point or it emits
#include <filesystem>
#include <string>
#include <vector>

#include "reference/PathTracer.h"

namespace lit {
struct Scene;
}

namespace lit::cli {

// False with `error` set when the file cannot be written. `hits` rows bottom-up, as the images.
bool writeNodeMap(const std::filesystem::path& path, const Scene& scene,
                  const std::vector<reference::FirstHit>& hits, int width, int height, std::string& error);

}  // namespace lit::cli
