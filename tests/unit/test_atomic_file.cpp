// Atomic file replacement (renderer/io/AtomicFile.cpp) and the image writers built on it
// (renderer/image/ImageIO.cpp).

#include <gtest/gtest.h>

#include "TempDir.h"
#include <stb/stb_image.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <csignal>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <functional>
#include <memory>
#include <set>

#include "image/ImageIO.h"
#include "io/AtomicFile.h"
#include "io/GltfFile.h"

namespace lit {
namespace {

namespace fs = std::filesystem;

// A folder of its own per test, removed afterwards.
struct TempDir : lit::testing::TempDir {
    TempDir() : lit::testing::TempDir("lit_atomic") {}
};

using testing::filesIn;
using testing::readText;

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(AtomicFile, WritesReplacesAndKeepsPermissions) {
    TempDir dir;
    const fs::path file = dir / "sub" / "folder" / "a.txt";
    writeFileAtomically(file, std::string_view("first"));
    EXPECT_EQ(readText(file), "first");
    ASSERT_EQ(::chmod(file.c_str(), 0640), 0);
    writeFileAtomically(file, std::string_view("second, longer"));
    EXPECT_EQ(readText(file), "second, longer");
    struct stat st{};
    ASSERT_EQ(::stat(file.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    EXPECT_EQ(filesIn(dir / "sub" / "folder"), std::set<std::string>{"a.txt"});  // no temporaries left
    writeFileAtomically(file, std::string_view(""));
    EXPECT_EQ(fs::file_size(file), 0u);
}

TEST(AtomicFile, ErrorsNameTheFileAndTheReason) {
    TempDir dir;
    fs::create_directories(dir / "folder");
    EXPECT_EQ(errorOf([&] { writeFileAtomically(dir / "folder", std::string_view("x")); }),
              (dir / "folder").string() + ": is a folder, not a file");
    std::ofstream(dir / "file") << "content";
    EXPECT_EQ(errorOf([&] { writeFileAtomically(dir / "file" / "child.txt", std::string_view("x")); }),
              (dir / "file" / "child.txt").string() + ": cannot create the file: " + (dir / "file").string() +
                  " is a file, not a folder");
    EXPECT_EQ(readText(dir / "file"), "content");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"folder", "file"}));
}

TEST(AtomicFile, ASymbolicLinkStaysALink) {
    TempDir dir;
    writeFileAtomically(dir / "real.txt", std::string_view("old"));
    fs::create_symlink("real.txt", dir / "link.txt");
    writeFileAtomically(dir / "link.txt", std::string_view("new"));
    EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
    EXPECT_EQ(readText(dir / "real.txt"), "new");
}

TEST(AtomicFileSet, UncommittedTemporariesAreRemoved) {
    TempDir dir;
    writeFileAtomically(dir / "a.bin", std::string_view("old a"));
    {
        AtomicFileSet files;
        files.stage(dir / "a.bin", std::string_view("new a"));
        files.stage(dir / "b.gltf", std::string_view("new b"));
        EXPECT_EQ(filesIn(dir.path()).size(), 3u);  // a.bin and two temporaries
    }
    EXPECT_EQ(filesIn(dir.path()), std::set<std::string>{"a.bin"});
    EXPECT_EQ(readText(dir / "a.bin"), "old a");

    AtomicFileSet twice;
    twice.stage(dir / "a.bin", std::string_view("1"));
    EXPECT_EQ(errorOf([&] { twice.stage(dir / "a.bin", std::string_view("2")); }),
              (dir / "a.bin").string() + ": is written twice in one save");
}

TEST(AtomicFileSet, AFailedRenameRestoresTheFilesAlreadyReplaced) {
    TempDir dir;
    writeFileAtomically(dir / "scene.bin", std::string_view("old bin"));
    writeFileAtomically(dir / "scene.gltf", std::string_view("old gltf"));
    AtomicFileSet files;
    files.stage(dir / "scene.bin", std::string_view("new bin"));
    files.stage(dir / "extra.bin", std::string_view("new extra"));  // did not exist before
    files.stage(dir / "scene.gltf", std::string_view("new gltf"));
    // Between staging and committing, the last target becomes a folder that is not empty, so
    // its rename fails after the first two succeeded.
    fs::remove(dir / "scene.gltf");
    fs::create_directories(dir / "scene.gltf" / "in the way");
    const std::string error = errorOf([&] { files.commit(); });
    EXPECT_EQ(error.rfind((dir / "scene.gltf").string() + ": cannot replace the file (", 0), 0u) << error;
    EXPECT_EQ(error.find("not restored"), std::string::npos) << error;
    EXPECT_EQ(readText(dir / "scene.bin"), "old bin");
    EXPECT_FALSE(fs::exists(dir / "extra.bin"));
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"scene.bin", "scene.gltf"}));  // no temporaries or backups
}

TEST(AtomicFileSet, CommitReplacesEveryFile) {
    TempDir dir;
    writeFileAtomically(dir / "scene.bin", std::string_view("old bin"));
    AtomicFileSet files;
    files.stage(dir / "scene.bin", std::string_view("new bin"));
    files.stage(dir / "scene.gltf", std::string_view("new gltf"));
    files.commit();
    EXPECT_EQ(readText(dir / "scene.bin"), "new bin");
    EXPECT_EQ(readText(dir / "scene.gltf"), "new gltf");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"scene.bin", "scene.gltf"}));
}

// The single commit point, proven at every step: a child process stages three files (buffer,
// sidecar, scene) and is SIGKILLed exactly at one step of commit(); after what the next start
// does (recoverInterruptedSaves) the three files are all old (killed before the journal) or all
// new (killed at or after it), and no temporary, backup or journal is left.
TEST(AtomicFileSet, AKillAtAnyStepIsAllOldOrAllNewAfterRecovery) {
    const std::vector<std::string> steps = {"staged", "backups", "journal", "renamed 1", "renamed 2", "renamed 3", "done"};
    const std::vector<std::string> names = {"scene.bin", "scene.gltf.lit.json", "scene.gltf"};
    for (std::size_t s = 0; s < steps.size(); ++s) {
        TempDir dir;
        for (const std::string& name : names) writeFileAtomically(dir / name, std::string_view("old " + name));
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            AtomicFileSet files;
            for (const std::string& name : names) files.stage(dir / name, std::string_view("new " + name));
            if (steps[s] == "staged") ::raise(SIGKILL);
            files.observeStepsForTesting([&](const std::string& step) {
                if (step == steps[s]) ::raise(SIGKILL);
            });
            files.commit();
            ::_exit(0);
        }
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << steps[s];
        EXPECT_GT(filesIn(dir.path()).size(), 0u);
        recoverInterruptedSaves(dir.path());
        const bool expectNew = s >= 2;  // the journal is the commit point
        for (const std::string& name : names)
            EXPECT_EQ(readText(dir / name), (expectNew ? "new " : "old ") + name) << "killed at " << steps[s];
        EXPECT_EQ(filesIn(dir.path()), std::set<std::string>(names.begin(), names.end())) << "killed at " << steps[s];
    }
}

TEST(AtomicFileSet, RecoveryLeavesOtherFilesAndLiveWritersAlone) {
    TempDir dir;
    std::ofstream(dir / "photo.tmp-1.png") << "a user's file";
    std::ofstream(dir / "notes.old-draft.txt") << "a user's file";
    const std::string live = "scene.bin.tmp-" + std::to_string(::getpid()) + "-abcdef12";
    std::ofstream(dir / live) << "being written by this process";
    std::ofstream(dir / "scene.bin.tmp-999999999-abcdef12") << "a dead writer's";  // no such pid
    std::ofstream(dir / "scene.bin.tmp-0a1b2c3d4e5f") << "an older version's";
    const std::vector<std::string> report = recoverInterruptedSaves(dir.path());
    EXPECT_EQ(report.size(), 2u);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"photo.tmp-1.png", "notes.old-draft.txt", live}));
}

TEST(GltfFileUris, PercentEncodingRoundTrips) {
    EXPECT_EQ(percentEncodePath("my textures/a+b 100%.png"), "my%20textures/a%2Bb%20100%25.png");
    EXPECT_EQ(percentDecode("my%20textures/a%2Bb%20100%25.png"), "my textures/a+b 100%.png");
    EXPECT_EQ(percentDecode("bad%zzend%2"), "bad%zzend%2");
    EXPECT_TRUE(staysInFolder("textures/a%20b.png"));
    EXPECT_FALSE(staysInFolder("../a.png"));
    EXPECT_FALSE(staysInFolder("a/%2E%2E/../b.png"));
    EXPECT_FALSE(staysInFolder("/etc/passwd"));
    EXPECT_TRUE(isDataUri("data:image/png;base64,AAAA"));
    const std::uint8_t bytes[] = {'M', 'a', 'n', 'y'};
    EXPECT_EQ(base64Encode(std::span(bytes, 4)), "TWFueQ==");
    EXPECT_EQ(base64Encode(std::span(bytes, 3)), "TWFu");
}

TEST(ImageIO, PngEncodesAndWritesRowsInFileOrder) {
    TempDir dir;
    // 2×2, given bottom-up: the first row written to the file is the second row given.
    const std::vector<std::uint8_t> rgba = {1, 2, 3, 255, 4, 5, 6, 255, 7, 8, 9, 255, 10, 11, 12, 128};
    const std::vector<std::uint8_t> png = encodePng(2, 2, rgba);
    int w = 0, h = 0, n = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> decoded(
        stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &w, &h, &n, 4), stbi_image_free);
    ASSERT_TRUE(decoded);
    ASSERT_EQ(w, 2);
    ASSERT_EQ(h, 2);
    const std::vector<std::uint8_t> top(decoded.get(), decoded.get() + 8);
    EXPECT_EQ(top, std::vector<std::uint8_t>(rgba.begin() + 8, rgba.end()));

    const fs::path file = dir / "out" / "image.png";
    writePng(file, 2, 2, rgba);
    EXPECT_EQ(testing::readFile(file), png);
    EXPECT_EQ(filesIn(dir / "out"), std::set<std::string>{"image.png"});

    EXPECT_EQ(errorOf([&] { writePng(dir / "small.png", 2, 2, std::span(rgba.data(), 15)); }),
              "cannot write " + (dir / "small.png").string() + ": 15 values given for a 2x2 image that needs 16");
    EXPECT_EQ(errorOf([&] { encodePng(0, 2, rgba); }), "cannot encode a PNG: image size 0x2 is empty");
    fs::create_directories(dir / "taken.hdr");
    const std::vector<float> rgb(12, 0.5f);
    EXPECT_EQ(errorOf([&] { writeHdr(dir / "taken.hdr", 2, 2, rgb); }),
              (dir / "taken.hdr").string() + ": is a folder, not a file");
}

TEST(ImageIO, HdrReadsBackWhatWriteHdrWrote) {
    TempDir dir;
    // 2×3, rows bottom-up as the renderer gives them; values of different exponents (RGBE keeps
    // an 8-bit mantissa per channel under a shared exponent: ~1 % of the largest channel).
    const std::vector<float> rgb = {0.5f, 0.25f, 0.125f, 2.0f, 4.0f, 8.0f,  1.0f,  1.0f, 1.0f,
                                    0.0f, 0.0f,  0.0f,   100.f, 50.f, 25.f, 0.01f, 0.02f, 0.04f};
    const fs::path file = dir / "image.hdr";
    writeHdr(file, 2, 3, rgb);
    const HdrImage image = readHdr(file);
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 3);
    ASSERT_EQ(image.rgb.size(), rgb.size());
    for (std::size_t i = 0; i < rgb.size(); i += 3) {
        const float largest = std::max({rgb[i], rgb[i + 1], rgb[i + 2]});
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_NEAR(image.rgb[i + c], rgb[i + c], 0.01f * largest) << "pixel " << i / 3 << " channel " << c;
    }

    writePng(dir / "image.png", 1, 1, std::vector<std::uint8_t>{1, 2, 3, 255});
    EXPECT_EQ(errorOf([&] { readHdr(dir / "image.png"); }),
              "cannot read " + (dir / "image.png").string() + ": not a Radiance .hdr image (or the file cannot be opened)");
    EXPECT_EQ(errorOf([&] { readHdr(dir / "missing.hdr"); }),
              "cannot read " + (dir / "missing.hdr").string() + ": not a Radiance .hdr image (or the file cannot be opened)");
}

}  // namespace
}  // namespace lit
