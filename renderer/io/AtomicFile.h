#pragma once
// Atomic file replacement: the content goes to "<file>.tmp-<random>" in the same folder, is
// flushed, and is renamed over `file`, so readers see the old file or the new one, never half
// of one, and a failed write leaves the old file untouched.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace lit {

// Creates the parent folder if needed. Throws std::runtime_error naming `file` and the reason.
void writeFileAtomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes);
void writeFileAtomically(const std::filesystem::path& file, std::string_view text);

// Several files replaced as one save (a .gltf and its .bin): stage() writes each file's
// temporary at once, beside its target; commit() renames them over their targets in the order
// they were staged, so stage the file that refers to the others last. When a rename fails, the
// files already replaced in this commit get their previous content back (kept as hard links
// until the commit succeeds), so a failed save leaves every old file as it was. Temporaries that
// were not committed are removed when the set is destroyed. A target that is a symbolic link is
// replaced where the link points, so the link stays.
class AtomicFileSet {
public:
    AtomicFileSet() = default;
    ~AtomicFileSet();
    AtomicFileSet(const AtomicFileSet&) = delete;
    AtomicFileSet& operator=(const AtomicFileSet&) = delete;

    // Creates the parent folder if needed. Throws std::runtime_error whose message starts with
    // `file` and gives the reason (the target is a folder, the parent is a file, the disk is full).
    void stage(const std::filesystem::path& file, std::span<const std::uint8_t> bytes);
    void stage(const std::filesystem::path& file, std::string_view text);
    // Throws std::runtime_error naming the file that could not be replaced; see above.
    void commit();

private:
    struct Entry {
        std::filesystem::path target;
        std::filesystem::path temporary;
    };
    std::vector<Entry> entries_;
};

}  // namespace lit
