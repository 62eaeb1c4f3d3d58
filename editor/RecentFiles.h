#pragma once
// Recently opened scenes, most recent first, kept in memory for the File menu.

#include <cstddef>
#include <filesystem>
#include <vector>

namespace lit::editor {

class RecentFiles {
public:
    explicit RecentFiles(std::size_t capacity = 10) : capacity_(capacity) {}

    // Moves `path` to the front (a path already listed is not repeated); the oldest entry
    // drops off when the list is full. Paths are compared after making them absolute and
    // lexically normal, so "a/../b.gltf" and "b.gltf" are one entry.
    void add(const std::filesystem::path& path);
    void remove(const std::filesystem::path& path);

    const std::vector<std::filesystem::path>& paths() const { return paths_; }
    bool empty() const { return paths_.empty(); }

private:
    std::size_t capacity_;
    std::vector<std::filesystem::path> paths_;
};

}  // namespace lit::editor
