#include "io/GltfGuard.h"

#include "io/GltfFile.h"
#include "io/LittleEndian.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"
#include "scene/SceneMemory.h"
#include "scene/Sheets.h"

#include <stb_image.h>
#include <tiny_gltf.h>

// POSIX: open/fstat/read, so that a file is checked (regular, size) on the very descriptor that
// is then read, not on a path that could change in between.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <system_error>

namespace lit {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
    throw SceneLoadError(file.string() + ": " + problem);
}

std::string megabytes(std::uint64_t bytes) {
    const std::uint64_t mb = (bytes + 500'000) / 1'000'000;
    return std::to_string(mb) + " MB";
}

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
    return a > std::numeric_limits<std::uint64_t>::max() - b ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

// Reads a whole regular file through one descriptor: the type and size are checked with fstat
// before the buffer is allocated. Returns an empty string on success, else the reason.
std::string readRegularFile(const fs::path& path, std::uint64_t maxBytes, std::vector<unsigned char>& out) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return std::generic_category().message(errno);
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat info{};
    if (::fstat(fd, &info) != 0) return std::generic_category().message(errno);
    if (S_ISDIR(info.st_mode)) return "is a folder, not a file";
    if (!S_ISREG(info.st_mode)) return "is not a regular file (a device, pipe or socket)";
    const auto size = static_cast<std::uint64_t>(info.st_size);
    if (size > maxBytes)
        return "is " + megabytes(size) + ", more than the limit of " + megabytes(maxBytes);
    out.resize(static_cast<std::size_t>(size));
    std::size_t done = 0;
    while (done < out.size()) {
        const ::ssize_t n = ::read(fd, out.data() + done, out.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return std::generic_category().message(errno);
        if (n == 0) break;  // shrank while we read: keep what is there, the size checks follow
        done += static_cast<std::size_t>(n);
    }
    out.resize(done);
    return {};
}

// ---------------------------------------------------------------------------------------------
// JSON pre-check: nlohmann's SAX parser is iterative, so depth and size are counted here without
// recursion; the parse stops at the first value past a limit.

class BoundedJsonCheck final : public nlohmann::json_sax<nlohmann::json> {
public:
    explicit BoundedJsonCheck(const GltfLimits& limits) : limits_(limits) {}

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(); }
    bool key(string_t&) override { return true; }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
        problem_ = "invalid JSON at byte " + std::to_string(position) + ": " + trimmed(e.what());
        return false;
    }

    const std::string& problem() const { return problem_; }

private:
    static std::string trimmed(std::string reason) {
        // "[json.exception.parse_error.101] parse error at line 3, ..." → "parse error at line 3, ..."
        if (const auto bracket = reason.find("] "); reason.starts_with("[json.exception") && bracket != std::string::npos)
            reason.erase(0, bracket + 2);
        return reason;
    }
    bool value() {
        if (++values_ > limits_.maxJsonValues) {
            problem_ = "the JSON has more than " + std::to_string(limits_.maxJsonValues) + " values (limit)";
            return false;
        }
        return true;
    }
    bool open() {
        if (!value()) return false;
        if (++depth_ > limits_.maxJsonDepth) {
            problem_ = "the JSON nests deeper than " + std::to_string(limits_.maxJsonDepth) + " levels (limit)";
            return false;
        }
        return true;
    }
    bool close() {
        --depth_;
        return true;
    }

    const GltfLimits& limits_;
    std::uint64_t values_ = 0;
    int depth_ = 0;
    std::string problem_;
};

// "scheme:" at the start of a URI (RFC 3986 §3.1): file:, http:, C: (a Windows drive) ...
bool hasScheme(std::string_view uri) {
    for (std::size_t i = 0; i < uri.size(); ++i) {
        const char c = uri[i];
        if (c == ':') return i > 0;
        const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
        if (!letter && (i == 0 || !((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.'))) return false;
    }
    return false;
}

// The scheme of a URI that has one, in lower case (schemes are case-insensitive, RFC 3986 §3.1).
std::string schemeOf(std::string_view uri) {
    std::string scheme(uri.substr(0, uri.find(':')));
    for (char& c : scheme) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return scheme;
}

// The local file a file: URI names (RFC 8089): "file:///a/b", "file://localhost/a/b" and
// "file:/a/b" name /a/b; percent-escapes in the path are decoded. Another host, or no absolute
// path, is an error.
fs::path fileUriPath(const fs::path& file, const std::string& what, const std::string& uri) {
    std::string_view rest = std::string_view(uri).substr(uri.find(':') + 1);
    if (rest.starts_with("//")) {
        rest.remove_prefix(2);
        const std::size_t slash = rest.find('/');
        std::string host(rest.substr(0, slash));
        for (char& c : host) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (!host.empty() && host != "localhost")
            fail(file, what + "'s uri '" + uri + "' names the host '" + host + "'; Lit reads local files only");
        rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash);
    }
    if (!rest.starts_with("/")) fail(file, what + "'s uri '" + uri + "' is not a file: URI with an absolute path (file:///...)");
    return fs::path(percentDecode(rest));
}

// What tinygltf makes of a URI before it joins it onto the scene's folder (its dlib::urldecode:
// %XX decoded, and '+' read as a space).
std::string tinygltfDecode(std::string_view uri) {
    const auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return 0;
    };
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            out += static_cast<char>((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

const nlohmann::json* member(const nlohmann::json& object, const char* name) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(name);
    return it == object.end() ? nullptr : &*it;
}

std::uint64_t nonNegative(const nlohmann::json* value) {
    if (!value || !value->is_number()) return 0;
    if (value->is_number_unsigned()) return value->get<std::uint64_t>();
    if (value->is_number_integer()) return static_cast<std::uint64_t>(std::max<std::int64_t>(0, value->get<std::int64_t>()));
    const double d = value->get<double>();
    return d > 0 ? (d >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max() : static_cast<std::uint64_t>(d)) : 0;
}

// Checks one buffer or image URI; returns the local file it names (empty for a data URI):
// relative to the scene's folder, or absolute for an absolute path or a file: URI.
// Images may name a relative path that goes up ("../textures/a.png": Lit's own Save As refers to
// the textures where they are instead of copying them); their bytes only ever become pixels,
// and a file that is not an image decodes to nothing. Buffers may not: their bytes become
// geometry and would be copied into the next save.
// Absolute paths and file: URIs (only with the opt-in) are added to `absoluteFiles`, keyed by
// what tinygltf will ask the file callbacks for: it joins every URI onto the scene's folder
// ("scenes/" + "/data/a.bin"), which the callbacks undo through this map.
fs::path checkUri(const fs::path& file, const std::string& what, const std::string& uri, const GltfLimits& limits,
                  std::map<std::string, fs::path>& absoluteFiles, bool image = false) {
    if (isDataUri(uri)) return {};
    if (uri.empty()) fail(file, what + " has an empty uri");
    const bool isFileUri = hasScheme(uri) && schemeOf(uri) == "file";
    if (hasScheme(uri) && !isFileUri)
        fail(file, what + "'s uri '" + uri + "' uses the scheme '" + schemeOf(uri) +
                       ":'; Lit reads buffers and images from data: URIs and local files only");
    const fs::path decoded(percentDecode(uri));
    const bool relative = !isFileUri && !decoded.is_absolute() && !decoded.has_root_name() && !decoded.has_root_directory();
    if (!limits.allowExternalUris && !(image ? relative : relative && staysInFolder(uri)))
        fail(file, what + "'s uri '" + uri +
                       "' points outside the scene's folder (absolute, '..' or a scheme such as file:); "
                       "only --allow-external-uris permits that");
    if (relative) return decoded;
    const fs::path local = isFileUri ? fileUriPath(file, what, uri) : decoded;
    absoluteFiles.emplace(tinygltfDecode(uri), local);
    return local;
}

// glTF 2.0 §3.2 / §5.2: a loader refuses a major version it does not know and a minVersion it
// does not implement.
void checkVersion(const fs::path& file, const nlohmann::json& doc) {
    const nlohmann::json* asset = member(doc, "asset");
    const nlohmann::json* version = asset ? member(*asset, "version") : nullptr;
    if (!asset) return;  // tinygltf says '"asset" object not found'
    if (!version || !version->is_string()) fail(file, "asset.version is missing; every glTF file must have one");
    const auto major = [](const std::string& text) -> long {
        const std::size_t dot = text.find('.');
        if (dot == 0 || dot == std::string::npos || dot > 6) return -1;
        for (std::size_t i = 0; i < dot; ++i)
            if (text[i] < '0' || text[i] > '9') return -1;
        return std::stol(text.substr(0, dot));
    };
    const std::string versionText = version->get<std::string>();
    const long versionMajor = major(versionText);
    if (versionMajor < 0) fail(file, "asset.version '" + versionText + "' is not of the form MAJOR.MINOR");
    if (versionMajor != 2)
        fail(file, "asset.version is '" + versionText + "'; Lit reads glTF 2.x only (the spec says to refuse other major versions)");
    if (const nlohmann::json* minVersion = member(*asset, "minVersion"); minVersion && minVersion->is_string()) {
        const std::string text = minVersion->get<std::string>();
        if (major(text) != 2 || text != "2.0")
            fail(file, "asset.minVersion is '" + text + "'; Lit implements glTF 2.0");
    }
}

// What the JSON declares: version, URIs and the bytes tinygltf will read for buffers and images.
void checkDeclarations(const fs::path& file, const nlohmann::json& doc, const GltfLimits& limits,
                       std::vector<fs::path>& externalImages, std::map<std::string, fs::path>& absoluteFiles) {
    if (!doc.is_object()) fail(file, "the JSON is not an object, so not a glTF file");
    checkVersion(file, doc);

    const fs::path folder = file.parent_path();
    std::uint64_t bufferBytes = 0;
    if (const nlohmann::json* buffers = member(doc, "buffers"); buffers && buffers->is_array()) {
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            const nlohmann::json& buffer = (*buffers)[i];
            const std::string what = "buffer " + std::to_string(i);
            if (const nlohmann::json* uri = member(buffer, "uri"); uri && uri->is_string())
                checkUri(file, what, uri->get<std::string>(), limits, absoluteFiles);
            // tinygltf allocates byteLength for every buffer (and insists the file has exactly
            // that many bytes), however many buffers name the same file.
            bufferBytes = saturatingAdd(bufferBytes, nonNegative(member(buffer, "byteLength")));
        }
        if (bufferBytes > limits.memoryBudgetBytes)
            fail(file, "its " + std::to_string(buffers->size()) + " buffers declare " + megabytes(bufferBytes) +
                           ", more than the memory budget of " + megabytes(limits.memoryBudgetBytes));
    }

    std::uint64_t imageBytes = 0;  // encoded bytes tinygltf reads or copies, once per image entry
    const nlohmann::json* views = member(doc, "bufferViews");
    if (const nlohmann::json* images = member(doc, "images"); images && images->is_array()) {
        std::map<fs::path, std::uint64_t> fileSizes;
        for (std::size_t i = 0; i < images->size(); ++i) {
            const nlohmann::json& image = (*images)[i];
            const std::string what = "image " + std::to_string(i);
            if (const nlohmann::json* uri = member(image, "uri"); uri && uri->is_string()) {
                const fs::path local = checkUri(file, what, uri->get<std::string>(), limits, absoluteFiles, /*image=*/true);
                if (local.empty()) continue;  // data URI: its bytes are in the JSON already
                auto [it, inserted] = fileSizes.try_emplace(local, 0);
                if (inserted) {
                    std::error_code ec;
                    const fs::path full = folder / local;
                    if (fs::is_regular_file(full, ec)) it->second = fs::file_size(full, ec);
                    if (ec) it->second = 0;
                }
                imageBytes = saturatingAdd(imageBytes, it->second);
                if (!staysInFolder(uri->get<std::string>())) {
                    std::error_code ec;
                    externalImages.push_back(fs::weakly_canonical(fs::absolute(folder / local, ec), ec));
                }
            } else if (const nlohmann::json* view = member(image, "bufferView"); view && view->is_number_unsigned() &&
                                                                                  views && views->is_array()) {
                const auto index = view->get<std::uint64_t>();
                if (index < views->size()) imageBytes = saturatingAdd(imageBytes, nonNegative(member((*views)[index], "byteLength")));
            }
        }
        if (imageBytes > limits.memoryBudgetBytes)
            fail(file, "its " + std::to_string(images->size()) + " images read " + megabytes(imageBytes) +
                           " of encoded data (the same file or buffer view counts once per image that names it), "
                           "more than the memory budget of " + megabytes(limits.memoryBudgetBytes));
    }
}

// True when `path` lies inside `folder` (both made canonical; symbolic links followed).
bool isInside(const fs::path& folder, const fs::path& path) {
    std::error_code ec;
    const fs::path canonicalPath = fs::weakly_canonical(path, ec);
    if (ec) return false;
    auto f = folder.begin();
    auto p = canonicalPath.begin();
    for (; f != folder.end(); ++f, ++p)
        if (p == canonicalPath.end() || *f != *p) return false;
    return true;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

void checkSceneFile(const fs::path& file, const GltfLimits& limits) {
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (ec || !fs::exists(status) || fs::is_directory(status)) return;  // the loader says which
    if (!fs::is_regular_file(status)) fail(file, "is not a regular file (a device, pipe or socket), not a glTF file");
    const std::uintmax_t size = fs::file_size(file, ec);
    if (!ec && size > limits.maxFileBytes)
        fail(file, "the file is " + megabytes(size) + ", more than the limit of " + megabytes(limits.maxFileBytes));
}

GuardedScene guardGltfFile(const fs::path& file, bool binary, const GltfLimits& limits) {
    GuardedScene scene;
    scene.binary = binary;
    if (const std::string problem = readRegularFile(file, limits.maxFileBytes, scene.bytes); !problem.empty())
        fail(file, problem);
    if (scene.bytes.empty()) fail(file, "the file is empty, not a glTF file");

    if (binary) {
        // GLB (glTF 2.0 §4.4): 12-byte header, then a chunk header (length, type "JSON") and the JSON.
        const std::size_t size = scene.bytes.size();
        if (size < 20) fail(file, "truncated GLB: shorter than its headers (20 bytes)");
        const unsigned char* bytes = scene.bytes.data();
        if (std::memcmp(bytes, "glTF", 4) != 0) fail(file, "not a GLB file (no \"glTF\" magic)");
        if (readLittleEndian32(bytes + 4) != 2) fail(file, "GLB container version is not 2");
        const std::uint64_t declared = readLittleEndian32(bytes + 8);
        const std::uint64_t jsonLength = readLittleEndian32(bytes + 12);
        if (declared > size) fail(file, "truncated GLB: the header declares " + std::to_string(declared) + " bytes, the file has " + std::to_string(size));
        if (readLittleEndian32(bytes + 16) != 0x4E4F534Au) fail(file, "the GLB's first chunk is not JSON");
        if (20 + jsonLength > declared) fail(file, "truncated GLB: the JSON chunk runs past the declared length");
        // The chunk after it is the buffer tinygltf reads (its own bound forgets the chunk's 8-byte
        // header, and the copy a compressed file is rewritten into ends at the declared length).
        if (const std::uint64_t next = 20 + jsonLength; next < declared) {
            if (next + 8 > declared)
                fail(file, "truncated GLB: " + std::to_string(declared - next) +
                               " bytes after the JSON chunk, too few for a chunk header (8 bytes)");
            const std::uint64_t chunkLength = readLittleEndian32(bytes + next);
            if (next + 8 + chunkLength > declared)
                fail(file, "truncated GLB: the chunk after the JSON declares " + std::to_string(chunkLength) +
                               " bytes, the file's declared length leaves " + std::to_string(declared - next - 8));
        }
        scene.json = std::string_view(reinterpret_cast<const char*>(bytes) + 20, static_cast<std::size_t>(jsonLength));
    } else {
        scene.json = std::string_view(reinterpret_cast<const char*>(scene.bytes.data()), scene.bytes.size());
    }

    BoundedJsonCheck check(limits);
    const bool ok = nlohmann::json::sax_parse(scene.json.begin(), scene.json.end(), &check,
                                              nlohmann::json::input_format_t::json, /*strict=*/true);
    if (!ok) fail(file, check.problem().empty() ? std::string("invalid JSON") : check.problem());

    // Within the limits, a DOM is safe to build: its depth and size are bounded now.
    const nlohmann::json doc = nlohmann::json::parse(scene.json.begin(), scene.json.end(), nullptr, /*exceptions=*/false);
    if (doc.is_discarded()) fail(file, "invalid JSON");
    checkDeclarations(file, doc, limits, scene.externalImages, scene.absoluteFiles);
    return scene;
}

// ---------------------------------------------------------------------------------------------

struct GuardedFileSystem::State {
    fs::path folder;  // canonical
    GltfLimits limits;
    std::vector<fs::path> externalImages;  // canonical; approved by the JSON check
    std::map<std::string, fs::path> absoluteFiles;  // approved by the JSON check (GuardedScene)
    // What tinygltf puts before a URI when it looks for the file: its JoinPath of the scene's
    // folder as the loader passes it ("" stays "", else a '/' is added) and of ".".
    std::vector<std::string> searchPrefixes;
    std::uint64_t bytesRead = 0;
    std::vector<std::string> refusals;
    std::set<std::string> refused;  // paths already reported

    void refuse(const std::string& path, const std::string& reason) {
        if (refused.insert(path).second) refusals.push_back("'" + path + "' " + reason);
    }
    // The file tinygltf means when it asks for `joined` (a URI joined onto a search folder).
    std::string resolve(const std::string& joined) const {
        for (const std::string& prefix : searchPrefixes) {
            if (!joined.starts_with(prefix)) continue;
            if (const auto it = absoluteFiles.find(joined.substr(prefix.size())); it != absoluteFiles.end())
                return it->second.string();
        }
        return joined;
    }
    bool allowed(const std::string& path) {
        if (limits.allowExternalUris) return true;
        if (isInside(folder, path)) return true;
        std::error_code canonicalError;
        const fs::path canonical = fs::weakly_canonical(fs::absolute(path, canonicalError), canonicalError);
        if (std::find(externalImages.begin(), externalImages.end(), canonical) != externalImages.end()) return true;
        std::error_code ec;
        if (fs::exists(path, ec)) refuse(path, "is outside the scene's folder (only --allow-external-uris permits that)");
        return false;
    }
};

GuardedFileSystem::GuardedFileSystem(const fs::path& sceneFile, const GltfLimits& limits,
                                     std::vector<fs::path> externalImages,
                                     std::map<std::string, fs::path> absoluteFiles)
    : state_(std::make_unique<State>()) {
    state_->externalImages = std::move(externalImages);
    state_->absoluteFiles = std::move(absoluteFiles);
    const std::string baseDir = sceneFile.parent_path().string();  // as the loader passes it to tinygltf
    state_->searchPrefixes = {baseDir.empty() || baseDir.ends_with('/') ? baseDir : baseDir + "/", "./"};
    std::error_code ec;
    const fs::path folder = sceneFile.parent_path().empty() ? fs::path(".") : sceneFile.parent_path();
    state_->folder = fs::weakly_canonical(fs::absolute(folder, ec), ec);
    state_->limits = limits;
}

GuardedFileSystem::~GuardedFileSystem() = default;

const std::vector<std::string>& GuardedFileSystem::refusals() const { return state_->refusals; }

tinygltf::FsCallbacks GuardedFileSystem::callbacks() {
    tinygltf::FsCallbacks fs{};
    fs.FileExists = [](const std::string& path, void* user) {
        auto& state = *static_cast<State*>(user);
        std::error_code ec;
        return state.allowed(path) && fs::is_regular_file(path, ec);
    };
    // tinygltf's default expands ~ and $VARIABLES through wordexp(3); a scene's URIs are plain
    // paths. Only an absolute path or file: URI, joined onto the folder by tinygltf, is mapped
    // back to the file it names.
    fs.ExpandFilePath = [](const std::string& path, void* user) { return static_cast<State*>(user)->resolve(path); };
    fs.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
        auto& state = *static_cast<State*>(user);
        if (!state.allowed(path)) {
            if (err) *err += "outside the scene's folder";
            return false;
        }
        // Every read counts against the budget, so that many entries naming one big file stop.
        const std::uint64_t left =
            state.bytesRead >= state.limits.memoryBudgetBytes ? 0 : state.limits.memoryBudgetBytes - state.bytesRead;
        const std::string problem = readRegularFile(path, std::min(left, state.limits.maxFileBytes), *out);
        if (!problem.empty()) {
            state.refuse(path, problem);
            if (err) *err += problem;
            out->clear();
            return false;
        }
        state.bytesRead += out->size();
        return true;
    };
    fs.WriteWholeFile = [](std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
        if (err) *err += "the loader writes no files";
        return false;
    };
    fs.user_data = state_.get();
    return fs;
}

// ---------------------------------------------------------------------------------------------

void ImageDeduplicator::add(int imageIndex, const unsigned char* bytes, std::size_t size) {
    if (imageIndex < 0) return;
    const auto index = static_cast<std::size_t>(imageIndex);
    if (entries_.size() <= index) entries_.resize(index + 1);
    Entry& entry = entries_[index];
    // FNV-1a over the bytes; equal hashes are confirmed byte by byte below.
    std::uint64_t hash = 1469598103934665603ull ^ size;
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    entry.hash = hash;
    entry.sameAs = -1;
    entry.bytes.clear();
    const auto [first, last] = byHash_.equal_range(hash);
    for (auto it = first; it != last; ++it) {
        const Entry& other = entries_[static_cast<std::size_t>(it->second)];
        if (other.bytes.size() != size || size == 0) continue;
        if (std::memcmp(other.bytes.data(), bytes, size) == 0) {
            entry.sameAs = it->second;
            ++duplicates_;
            return;
        }
    }
    byHash_.emplace(hash, imageIndex);
    if (bytes && size > 0) entry.bytes.assign(bytes, bytes + size);
}

int ImageDeduplicator::canonical(int imageIndex) const {
    if (imageIndex < 0 || static_cast<std::size_t>(imageIndex) >= entries_.size()) return imageIndex;
    const int sameAs = entries_[static_cast<std::size_t>(imageIndex)].sameAs;
    return sameAs >= 0 ? sameAs : imageIndex;
}

std::vector<unsigned char> ImageDeduplicator::take(int imageIndex) {
    if (imageIndex < 0 || static_cast<std::size_t>(imageIndex) >= entries_.size()) return {};
    return std::move(entries_[static_cast<std::size_t>(imageIndex)].bytes);
}

// ---------------------------------------------------------------------------------------------

void checkMemoryBudget(const fs::path& file, const tinygltf::Model& model, const ImageDeduplicator& images,
                       const GltfLimits& limits) {
    // An accessor's count as far as its data can back it: every element takes at least one byte
    // of its buffer view, so a count beyond the view's length is invalid and left to the loader's
    // precise message ("reads past the end of buffer view 3"), not counted here.
    const auto count = [&](int accessor) -> std::uint64_t {
        if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size()) return 0;
        const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor)];
        if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size()) return 0;
        const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
        return a.count <= view.byteLength ? a.count : 0;
    };
    // Geometry as the scene builder makes it: every primitive on its own (primitives that share
    // accessors are built once each), unwelded to one vertex per index when normals are computed.
    std::uint64_t geometryVertices = 0, geometryIndices = 0;
    std::size_t primitives = 0;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives) {
            ++primitives;
            const auto position = primitive.attributes.find("POSITION");
            const std::uint64_t vertices = position == primitive.attributes.end() ? 0 : count(position->second);
            const std::uint64_t indices = primitive.indices >= 0 ? count(primitive.indices) : vertices;
            geometryVertices = saturatingAdd(geometryVertices, std::max(vertices, indices));
            geometryIndices = saturatingAdd(geometryIndices, indices);
        }

    // Images Lit decodes (each distinct image once, its size from its header) and which of them a
    // texture uses (then GpuScene uploads it, once however many textures share it).
    std::vector<std::uint8_t> textured(model.images.size(), 0);
    for (const tinygltf::Texture& texture : model.textures)
        if (texture.source >= 0 && static_cast<std::size_t>(texture.source) < model.images.size())
            textured[static_cast<std::size_t>(images.canonical(texture.source))] = 1;
    std::vector<ImageExtent> extents;
    std::uint64_t largestImage = 0;
    std::size_t largestIndex = 0;
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        if (images.canonical(static_cast<int>(i)) != static_cast<int>(i)) continue;
        const std::vector<unsigned char>& encoded = model.images[i].image;
        int width = 0, height = 0, channels = 0;
        if (encoded.empty() || encoded.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
            !stbi_info_from_memory(encoded.data(), static_cast<int>(encoded.size()), &width, &height, &channels))
            continue;  // not decodable: becomes 1×1 white
        extents.push_back({width, height, textured[i] != 0});
        const std::uint64_t bytes = textureBytesWithMips(width, height);
        if (bytes > largestImage) {
            largestImage = bytes;
            largestIndex = i;
        }
    }

    // The shadow maps: every node that holds a light (an upper bound: unreachable nodes and lights
    // that cast no shadow count too), and the sheets (drawnAsSheet).
    ShadowCasters casters;
    bool anyLight = false;
    for (const tinygltf::Node& node : model.nodes) {
        const auto punctual = node.extensions.find("KHR_lights_punctual");
        if (punctual == node.extensions.end() || !punctual->second.Has("light")) continue;
        const tinygltf::Value& index = punctual->second.Get("light");
        if (!index.IsInt() || index.GetNumberAsInt() < 0 || static_cast<std::size_t>(index.GetNumberAsInt()) >= model.lights.size())
            continue;  // the importer names the bad reference
        anyLight = true;
        (model.lights[static_cast<std::size_t>(index.GetNumberAsInt())].type == "point" ? casters.cubes : casters.maps2d) += 1;
    }
    if (!anyLight) casters.maps2d = 1;
    for (const tinygltf::Material& material : model.materials) {
        const auto transmission = material.extensions.find("KHR_materials_transmission");
        if (transmission == material.extensions.end() || !transmission->second.Has("transmissionFactor")) continue;
        const tinygltf::Value& factor = transmission->second.Get("transmissionFactor");
        if (factor.IsNumber() && drawnAsSheet(factor.GetNumberAsDouble(), material.pbrMetallicRoughness.metallicFactor))
            casters.sheets = true;
    }
    const SceneMemory memory = estimateSceneMemory(extents, geometryVertices, geometryIndices, casters, limits.render);
    const std::optional<std::string> over =
        overMemoryLimit(memory, {limits.memoryBudgetBytes, limits.memoryBudgetSource});
    if (!over) return;
    // Where the file's images or geometry are the largest part, name what is behind it: the
    // largest image, or the primitive count (the render settings' parts speak for themselves).
    const std::uint64_t imageBytes = memory.textures + memory.decodedImages;
    const std::uint64_t renderBytes = std::max({memory.voxels, memory.rayHits, memory.targets, memory.shadowMaps});
    std::string cause;
    if (imageBytes >= memory.geometry && imageBytes >= renderBytes && !extents.empty())
        cause = "; " + std::to_string(extents.size()) + " distinct images, the largest image " +
                std::to_string(largestIndex) + " alone " + formatBytes(largestImage, memory.total()) + " with mipmaps";
    else if (memory.geometry > imageBytes && memory.geometry >= renderBytes)
        cause = "; geometry of " + std::to_string(primitives) + " primitives";
    fail(file, *over + cause);
}

}  // namespace lit
