#include "io/AtomicFile.h"

// POSIX for fsync (std::ofstream cannot flush to the disk) and for link (the backups of commit).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace lit {

namespace fs = std::filesystem;

namespace {

std::string randomSuffix() {
    std::random_device random;
    std::ostringstream text;
    text << std::hex << random() << random();
    return text.str();
}

std::string errnoText(int error) { return std::generic_category().message(error); }

[[noreturn]] void fail(const fs::path& file, const std::string& reason) {
    throw std::runtime_error(file.string() + ": " + reason);
}

// Writes all of `bytes` to a new file `temporary` and flushes it to the disk; it gets the
// permissions of `target` when that exists. Removes `temporary` and throws on failure.
void writeNewFile(const fs::path& target, const fs::path& temporary, std::span<const std::uint8_t> bytes) {
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail(target, "cannot create the temporary file " + temporary.string() + " (" + errnoText(errno) + ")");
    // A replaced file keeps its permissions (a read-only scene stays read-only to others).
    struct stat old{};
    if (::stat(target.c_str(), &old) == 0) (void)::fchmod(fd, old.st_mode & 07777);

    const auto failHere = [&](const std::string& what) {
        const int error = errno;
        ::close(fd);
        ::unlink(temporary.c_str());
        fail(target, what + " " + temporary.string() + " (" + errnoText(error) + ")");
    };
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ::ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) failHere("cannot write the temporary file");
        written += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) failHere("cannot flush the temporary file");
    if (::close(fd) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        fail(target, "cannot close the temporary file " + temporary.string() + " (" + errnoText(error) + ")");
    }
}

// Makes a rename durable: the folder's entry is flushed too (best effort; some file systems
// refuse fsync on folders).
void syncFolder(const fs::path& folder) {
    const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
}

}  // namespace

AtomicFileSet::~AtomicFileSet() {
    for (const Entry& entry : entries_) ::unlink(entry.temporary.c_str());
}

void AtomicFileSet::stage(const fs::path& file, std::span<const std::uint8_t> bytes) {
    if (file.empty() || !file.has_filename()) fail(file, "not a file name");
    std::error_code ec;
    fs::path target = file;
    // Replace what a symbolic link points to, not the link.
    if (fs::is_symlink(fs::symlink_status(file, ec))) {
        target = fs::weakly_canonical(file, ec);
        if (ec) fail(file, "cannot follow the symbolic link (" + ec.message() + ")");
    }
    const fs::path folder = target.parent_path();
    if (!folder.empty()) {
        const fs::file_status status = fs::status(folder, ec);
        if (fs::exists(status) && !fs::is_directory(status))
            fail(file, "cannot create the file: " + folder.string() + " is a file, not a folder");
        fs::create_directories(folder, ec);
        if (ec) fail(file, "cannot create the folder " + folder.string() + " (" + ec.message() + ")");
    }
    if (fs::is_directory(fs::status(target, ec))) fail(file, "is a folder, not a file");
    for (const Entry& entry : entries_)
        if (entry.target == target) fail(file, "is written twice in one save");

    const fs::path temporary = folder / (target.filename().string() + ".tmp-" + randomSuffix());
    writeNewFile(target, temporary, bytes);
    entries_.push_back({target, temporary});
}

void AtomicFileSet::stage(const fs::path& file, std::string_view text) {
    stage(file, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void AtomicFileSet::commit() {
    // Backups are only needed when a later rename can fail after an earlier one succeeded.
    const bool keepBackups = entries_.size() > 1;
    struct Done {
        fs::path target;
        fs::path backup;  // empty: there was no previous file (or it could not be linked)
        bool hadFile = false;
    };
    std::vector<Done> done;
    std::set<fs::path> folders;

    for (std::size_t i = 0; i < entries_.size(); ++i) {
        const Entry& entry = entries_[i];
        Done record{entry.target, {}, false};
        struct stat old{};
        record.hadFile = ::lstat(entry.target.c_str(), &old) == 0;
        if (keepBackups && record.hadFile) {
            const fs::path backup = entry.target.parent_path() / (entry.target.filename().string() + ".old-" + randomSuffix());
            // A file system without hard links gets no backup: that file cannot be rolled back.
            if (::link(entry.target.c_str(), backup.c_str()) == 0) record.backup = backup;
        }
        if (::rename(entry.temporary.c_str(), entry.target.c_str()) != 0) {
            const int error = errno;
            if (!record.backup.empty()) ::unlink(record.backup.c_str());
            // Put back what this commit already replaced, newest first.
            std::string lost;
            for (auto d = done.rbegin(); d != done.rend(); ++d) {
                if (!d->backup.empty()) {
                    if (::rename(d->backup.c_str(), d->target.c_str()) == 0) {
                        d->backup.clear();
                    } else {
                        lost += (lost.empty() ? "" : ", ") + d->target.string() + " (its previous content is in " +
                                d->backup.string() + ")";
                    }
                } else if (!d->hadFile) {
                    ::unlink(d->target.c_str());  // it did not exist before this commit
                } else {
                    lost += (lost.empty() ? "" : ", ") + d->target.string();
                }
            }
            const fs::path failed = entry.target;  // `entry` goes with entries_
            for (std::size_t j = i; j < entries_.size(); ++j) ::unlink(entries_[j].temporary.c_str());
            entries_.clear();
            std::string message = "cannot replace the file (" + errnoText(error) + ")";
            if (!lost.empty()) message += "; already replaced and not restored: " + lost;
            fail(failed, message);
        }
        done.push_back(std::move(record));
        folders.insert(entry.target.parent_path());
    }
    for (const Done& d : done)
        if (!d.backup.empty()) ::unlink(d.backup.c_str());
    entries_.clear();
    for (const fs::path& folder : folders) syncFolder(folder);
}

void writeFileAtomically(const fs::path& file, std::span<const std::uint8_t> bytes) {
    AtomicFileSet files;
    files.stage(file, bytes);
    files.commit();
}

void writeFileAtomically(const fs::path& file, std::string_view text) {
    AtomicFileSet files;
    files.stage(file, text);
    files.commit();
}

}  // namespace lit
