#include "io/AtomicFile.h"

// POSIX for fsync (std::ofstream cannot flush to the disk) and for link (the backups of commit).
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace lit {

namespace fs = std::filesystem;

namespace {

// "<pid>-<random hex>": the pid tells recovery whether the writer still runs.
std::string randomSuffix() {
    std::random_device random;
    std::ostringstream text;
    text << ::getpid() << '-' << std::hex << random() << random();
    return text.str();
}

constexpr std::string_view kTemporary = ".tmp-";
constexpr std::string_view kBackup = ".old-";
constexpr std::string_view kJournal = ".lit-journal-";

bool processRuns(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

// The writer's pid in "<name><marker><pid>-<hex>"; 0 for an older version's "<name>.tmp-<hex>"
// (at least 8 hex digits; stale by now); -1 when the name is not one of ours.
long writerPid(const std::string& name, std::string_view marker) {
    const std::size_t at = name.rfind(marker);
    if (at == std::string::npos || at == 0) return -1;
    const std::string_view rest = std::string_view(name).substr(at + marker.size());
    const auto isHex = [](std::string_view text) {
        return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
            return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
        });
    };
    const std::size_t dash = rest.find('-');
    if (dash == std::string_view::npos) return marker == kTemporary && rest.size() >= 8 && isHex(rest) ? 0 : -1;
    const std::string_view digits = rest.substr(0, dash);
    if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }) ||
        !isHex(rest.substr(dash + 1)))
        return -1;
    return std::stol(std::string(digits));
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
    (void)recoverInterruptedSaves(folder.empty() ? fs::path(".") : folder);  // "cleaned on the next save"
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

    const fs::path temporary = folder / (target.filename().string() + std::string(kTemporary) + randomSuffix());
    writeNewFile(target, temporary, bytes);
    entries_.push_back({target, temporary});
}

void AtomicFileSet::stage(const fs::path& file, std::string_view text) {
    stage(file, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void AtomicFileSet::commit() {
    const auto step = [&](const std::string& name) {
        if (observer_) observer_(name);
    };
    // One file: its rename is the commit point. Several: backups, then the journal.
    const bool journaled = entries_.size() > 1;
    struct Done {
        fs::path target;
        fs::path backup;  // empty: there was no previous file (or it could not be linked)
        bool hadFile = false;
    };
    std::vector<Done> records;
    std::set<fs::path> folders;
    for (const Entry& entry : entries_) {
        Done record{entry.target, {}, false};
        struct stat old{};
        record.hadFile = ::lstat(entry.target.c_str(), &old) == 0;
        if (journaled && record.hadFile) {
            const fs::path backup =
                entry.target.parent_path() / (entry.target.filename().string() + std::string(kBackup) + randomSuffix());
            // A file system without hard links gets no backup: that file cannot be rolled back
            // in-process (a crash is still rolled forward by the journal).
            if (::link(entry.target.c_str(), backup.c_str()) == 0) record.backup = backup;
        }
        records.push_back(std::move(record));
        folders.insert(entry.target.parent_path());
    }
    step("backups");

    fs::path journal;
    if (journaled) {
        const fs::path& last = entries_.back().target;
        const fs::path home = last.parent_path();
        journal = home / (last.filename().string() + std::string(kJournal) + randomSuffix());
        const auto relative = [&](const fs::path& path) { return path.lexically_relative(home.empty() ? fs::path(".") : home).string(); };
        nlohmann::json entries = nlohmann::json::array();
        for (std::size_t i = 0; i < entries_.size(); ++i)
            entries.push_back({{"target", relative(entries_[i].target)},
                               {"temporary", relative(entries_[i].temporary)},
                               {"backup", records[i].backup.empty() ? std::string() : relative(records[i].backup)}});
        const std::string text = nlohmann::json{{"version", 1}, {"entries", entries}}.dump() + "\n";
        const fs::path journalTemporary = journal.string() + std::string(kTemporary) + randomSuffix();
        try {
            writeNewFile(journal, journalTemporary,
                         std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
        } catch (...) {
            for (const Done& d : records)
                if (!d.backup.empty()) ::unlink(d.backup.c_str());
            throw;
        }
        if (::rename(journalTemporary.c_str(), journal.c_str()) != 0) {
            const int error = errno;
            ::unlink(journalTemporary.c_str());
            for (const Done& d : records)
                if (!d.backup.empty()) ::unlink(d.backup.c_str());
            fail(journal, "cannot write the save's journal (" + errnoText(error) + ")");
        }
        syncFolder(home);  // the commit point is on the disk
    }
    step("journal");

    for (std::size_t i = 0; i < entries_.size(); ++i) {
        const Entry& entry = entries_[i];
        if (::rename(entry.temporary.c_str(), entry.target.c_str()) != 0) {
            const int error = errno;
            // Put back what this commit already replaced, newest first.
            std::string lost;
            for (std::size_t k = i; k-- > 0;) {
                Done& d = records[k];
                if (!d.backup.empty()) {
                    if (::rename(d.backup.c_str(), d.target.c_str()) == 0) {
                        d.backup.clear();
                    } else {
                        lost += (lost.empty() ? "" : ", ") + d.target.string() + " (its previous content is in " +
                                d.backup.string() + ")";
                    }
                } else if (!d.hadFile) {
                    ::unlink(d.target.c_str());  // it did not exist before this commit
                } else {
                    lost += (lost.empty() ? "" : ", ") + d.target.string();
                }
            }
            for (std::size_t k = i; k < records.size(); ++k)
                if (!records[k].backup.empty()) ::unlink(records[k].backup.c_str());
            const fs::path failed = entry.target;  // `entry` goes with entries_
            for (std::size_t j = i; j < entries_.size(); ++j) ::unlink(entries_[j].temporary.c_str());
            entries_.clear();
            // Rolled back by hand: the journal must not roll it forward again.
            if (!journal.empty() && lost.empty()) ::unlink(journal.c_str());
            std::string message = "cannot replace the file (" + errnoText(error) + ")";
            if (!lost.empty()) message += "; already replaced and not restored: " + lost;
            fail(failed, message);
        }
        step("renamed " + std::to_string(i + 1));
    }
    entries_.clear();
    for (const fs::path& folder : folders) syncFolder(folder);
    for (const Done& d : records)
        if (!d.backup.empty()) ::unlink(d.backup.c_str());
    if (!journal.empty()) {
        ::unlink(journal.c_str());
        syncFolder(journal.parent_path());
    }
    step("done");
}

std::vector<std::string> recoverInterruptedSaves(const fs::path& folder) {
    std::vector<std::string> report;
    std::error_code ec;
    std::vector<fs::path> names;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) names.push_back(it->path());
    if (ec) return report;
    const long self = static_cast<long>(::getpid());
    const auto stale = [&](long pid) { return pid == 0 || (pid > 0 && pid != self && !processRuns(pid)); };

    // Roll forward every journal of a writer that is gone: its save had reached the commit point.
    bool changed = false;
    for (const fs::path& path : names) {
        const std::string name = path.filename().string();
        if (name.find(kJournal) == std::string::npos || name.find(kTemporary) != std::string::npos) continue;
        if (!stale(writerPid(name, kJournal))) continue;
        std::ifstream in(path, std::ios::binary);
        const nlohmann::json journal = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
        if (journal.is_object() && journal.contains("entries") && journal["entries"].is_array()) {
            for (const nlohmann::json& entry : journal["entries"]) {
                if (!entry.is_object()) continue;
                const auto text = [&](const char* key) {
                    const auto it = entry.find(key);
                    return it != entry.end() && it->is_string() ? it->get<std::string>() : std::string();
                };
                const std::string target = text("target"), temporary = text("temporary"), backup = text("backup");
                if (target.empty() || temporary.empty()) continue;
                const fs::path temporaryPath = folder / temporary;
                if (fs::exists(temporaryPath, ec) && ::rename(temporaryPath.c_str(), (folder / target).c_str()) == 0)
                    report.push_back((folder / target).string() + ": finished an interrupted save");
                if (!backup.empty()) ::unlink((folder / backup).c_str());
            }
        }
        ::unlink(path.c_str());
        changed = true;
    }

    // Temporaries and backups nobody will commit or restore any more.
    for (const fs::path& path : names) {
        const std::string name = path.filename().string();
        for (const std::string_view marker : {kTemporary, kBackup}) {
            const long pid = writerPid(name, marker);
            if (pid < 0 || !stale(pid)) continue;
            if (!fs::is_regular_file(fs::symlink_status(path, ec))) continue;
            if (::unlink(path.c_str()) == 0) {
                report.push_back(path.string() + ": removed, left by an interrupted save");
                changed = true;
            }
            break;
        }
    }
    if (changed) syncFolder(folder);
    return report;
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
