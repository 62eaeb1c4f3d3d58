#pragma once
// Atomic file replacement: the content goes to "<file>.tmp-<pid>-<random>" in the same folder, is
// flushed, and is renamed over `file`, so readers see the old file or the new one, never half
// of one, and a failed write leaves the old file untouched.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <span>
#include <string_view>
#include <vector>

namespace lit {

// Creates the parent folder if needed. Throws std::runtime_error naming `file` and the reason.
void writeFileAtomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes);
void writeFileAtomically(const std::filesystem::path& file, std::string_view text);

// Several files replaced as one save (a .gltf and its .bin) with a single commit point.
//
// stage() writes each file's temporary "<target>.tmp-<pid>-<random>" beside its target and
// flushes it. commit() then
//   1. links each existing target to "<target>.old-<pid>-<random>" (for an in-process rollback),
//   2. writes the journal "<last target>.lit-journal-<pid>-<random>" (target, temporary and
//      backup of every file) atomically: THE COMMIT POINT,
//   3. renames the temporaries over their targets in the order they were staged,
//   4. removes the backups and the journal.
// A crash before the journal exists leaves every old file as it was (the temporaries and backups
// are stale); a crash after it is rolled forward by recoverInterruptedSaves(), which renames the
// temporaries that are still there. So after recovery the files are all old or all new, never a
// mix. A single-file set needs no journal: its one rename is the commit point.
// When a rename fails in-process, the files already replaced get their previous content back
// from the backups and the journal is removed, so a failed save leaves every old file as it was.
// Temporaries that were not committed are removed when the set is destroyed. A target that is a
// symbolic link is replaced where the link points, so the link stays.
class AtomicFileSet {
public:
    AtomicFileSet() = default;
    ~AtomicFileSet();
    AtomicFileSet(const AtomicFileSet&) = delete;
    AtomicFileSet& operator=(const AtomicFileSet&) = delete;

    // Creates the parent folder if needed, and first recovers interrupted saves in it (see
    // recoverInterruptedSaves). Throws std::runtime_error whose message starts with `file` and
    // gives the reason (the target is a folder, the parent is a file, the disk is full).
    void stage(const std::filesystem::path& file, std::span<const std::uint8_t> bytes);
    void stage(const std::filesystem::path& file, std::string_view text);
    // Throws std::runtime_error naming the file that could not be replaced; see above.
    void commit();

    // Tests only: called with the name of each step of commit() as it is reached ("backups",
    // "journal", "renamed <n>", "done"), so that a test can kill the process exactly there.
    void observeStepsForTesting(std::function<void(const std::string&)> observer) { observer_ = std::move(observer); }

private:
    struct Entry {
        std::filesystem::path target;
        std::filesystem::path temporary;
    };
    std::vector<Entry> entries_;
    std::function<void(const std::string&)> observer_;
};

// Finishes or undoes the saves in `folder` that a process which no longer runs left behind: a
// journal's temporaries are renamed over their targets (the save had reached its commit point),
// then stale temporaries, backups and journals are removed. Files of running processes are left
// alone. Returns one line per file it changed (for a log); never throws.
std::vector<std::string> recoverInterruptedSaves(const std::filesystem::path& folder);

}  // namespace lit
