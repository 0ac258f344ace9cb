#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>

#include <atomic>
#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "rasterlab/file_io.hpp"
#include "temp_dir.hpp"

namespace {

std::size_t entries(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir),
                                                  std::filesystem::directory_iterator()));
}

TEST(FileIo, AtomicWriteReplacesTheWholeFile) {
    rl_test::TempDir dir;
    const auto path = dir.path() / "data.bin";
    const std::vector<std::uint8_t> first(1000, 1), second = {9, 8, 7};
    rl::write_file_atomically(path, first);
    rl::write_file_atomically(path, second);
    EXPECT_EQ(rl::read_file(path), second);
    EXPECT_EQ(entries(dir.path()), 1u);  // no temporary left over
}

TEST(FileIo, FailedRenameRemovesTheTemporaryAndKeepsTheTarget) {
    rl_test::TempDir dir;
    // A non-empty directory cannot be replaced by a file: the rename fails.
    const auto target = dir.path() / "occupied";
    std::filesystem::create_directory(target);
    rl_test::write_text(target / "inside.txt", "keep me");
    const std::vector<std::uint8_t> bytes = {1, 2, 3};
    EXPECT_THROW(rl::write_file_atomically(target, bytes), rl::FileError);
    EXPECT_EQ(entries(dir.path()), 1u);
    EXPECT_TRUE(std::filesystem::exists(target / "inside.txt"));
}

TEST(FileIo, ErrorsNameThePath) {
    rl_test::TempDir dir;
    const auto missing = dir.path() / "missing.bin";
    try {
        rl::read_file(missing);
        FAIL();
    } catch (const rl::FileError& e) {
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos);
    }
}

// ---------------------------------------------------------------------------
// Reading: regular files only, never more than the cap.

std::string message_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const rl::FileError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(FileIo, DevicesAndFifosAreRefusedWithoutReading) {
    // /dev/zero would be read until memory runs out; a FIFO would wait forever.
    EXPECT_NE(message_of([] { rl::read_file("/dev/zero"); }).find("not a regular file"),
              std::string::npos);
    rl_test::TempDir dir;
    const auto fifo = dir.path() / "pipe.tga";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(message_of([&] { rl::read_file(fifo); }).find("not a regular file"),
              std::string::npos);
}

TEST(FileIo, FilesOverTheCapAreRefusedNamingTheCap) {
    rl_test::TempDir dir;
    const auto path = dir.path() / "big.bin";
    rl_test::write_text(path, std::string(3u << 20, 'x'));  // 3 MiB
    EXPECT_EQ(rl::read_file(path, 3u << 20).size(), 3u << 20);
    const std::string message = message_of([&] { rl::read_file(path, 2u << 20); });
    EXPECT_NE(message.find("more than the 2 MiB"), std::string::npos) << message;
}

// ---------------------------------------------------------------------------
// Writing: through links, never over what is not ours to replace.

TEST(FileIo, ReadOnlyFilesAreRefusedAndKept) {
    rl_test::TempDir dir;
    const auto path = dir.path() / "keep.tga";
    rl_test::write_text(path, "old");
    std::filesystem::permissions(path, std::filesystem::perms::owner_read);
    const std::vector<std::uint8_t> bytes = {1, 2, 3};
    EXPECT_NE(message_of([&] { rl::write_file_atomically(path, bytes); }).find("read-only"),
              std::string::npos);
    EXPECT_EQ(rl::read_file(path), (std::vector<std::uint8_t>{'o', 'l', 'd'}));
    EXPECT_EQ(std::filesystem::status(path).permissions(), std::filesystem::perms::owner_read);
    EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(FileIo, DevicesAreNeverReplaced) {
    // Checked, not written: as root a rename would replace /dev/null itself.
    EXPECT_NE(message_of([] { rl::check_output("/dev/null"); }).find("not a regular file"),
              std::string::npos);
    rl_test::TempDir dir;
    const auto fifo = dir.path() / "pipe.tga";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const std::vector<std::uint8_t> bytes = {1};
    EXPECT_THROW(rl::write_file_atomically(fifo, bytes), rl::FileError);
    EXPECT_TRUE(std::filesystem::is_fifo(fifo));
}

TEST(FileIo, SymbolicLinksAreWrittenThrough) {
    rl_test::TempDir dir;
    std::filesystem::create_directory(dir.path() / "real");
    const auto target = dir.path() / "real" / "image.tga";
    rl_test::write_text(target, "old");
    const auto link = dir.path() / "link.tga";
    std::filesystem::create_symlink("real/image.tga", link);  // relative, as users make them
    const std::vector<std::uint8_t> bytes = {4, 5};
    rl::write_file_atomically(link, bytes);
    EXPECT_TRUE(std::filesystem::is_symlink(link));
    EXPECT_EQ(rl::read_file(target), bytes);
    // A dangling link creates its target.
    const auto dangling = dir.path() / "dangling.tga";
    std::filesystem::create_symlink("real/new.tga", dangling);
    rl::write_file_atomically(dangling, bytes);
    EXPECT_TRUE(std::filesystem::is_symlink(dangling));
    EXPECT_EQ(rl::read_file(dir.path() / "real" / "new.tga"), bytes);
}

TEST(FileIo, ReplacingKeepsTheFilesPermissions) {
    rl_test::TempDir dir;
    const auto path = dir.path() / "private.tga";
    rl_test::write_text(path, "old");
    const auto mode = std::filesystem::perms::owner_read | std::filesystem::perms::owner_write;
    std::filesystem::permissions(path, mode);
    const std::vector<std::uint8_t> bytes = {1};
    rl::write_file_atomically(path, bytes);
    EXPECT_EQ(std::filesystem::status(path).permissions(), mode);
}

TEST(FileIo, ALongestFileNameWorksAndTemporariesAreRecognisable) {
    rl_test::TempDir dir;
    const auto path = dir.path() / (std::string(251, 'n') + ".tga");  // 255 bytes
    const std::vector<std::uint8_t> bytes = {7};
    rl::write_file_atomically(path, bytes);
    EXPECT_EQ(rl::read_file(path), bytes);
    {
        rl::OutputFiles out;
        out.stage(dir.path() / "a.tga", bytes);
        bool found = false;
        for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
            found |= entry.path().filename().string().starts_with(rl::kTemporaryPrefix);
        EXPECT_TRUE(found);
    }  // not committed: the temporary goes, nothing is written
    EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(FileIo, OutputSetsAreAllOrNothing) {
    rl_test::TempDir dir;
    const auto first = dir.path() / "first.tga", second = dir.path() / "second.tga";
    rl_test::write_text(first, "old");
    const std::vector<std::uint8_t> bytes = {1, 2};
    {
        rl::OutputFiles out;
        out.stage(first, bytes);
        EXPECT_THROW(out.stage(dir.path() / "absent" / "second.tga", bytes), rl::FileError);
    }
    EXPECT_EQ(rl::read_file(first), (std::vector<std::uint8_t>{'o', 'l', 'd'}));
    rl::forget_inputs();  // read back to check it, not an input of what follows
    rl::OutputFiles both;
    both.stage(first, bytes);
    both.stage(second, bytes);
    both.commit();
    EXPECT_EQ(rl::read_file(first), bytes);
    EXPECT_EQ(rl::read_file(second), bytes);
    EXPECT_EQ(entries(dir.path()), 2u);
}

// No output may replace a file the run has read, by its own name, a
// symbolic link or a hard link (issue 17: 07_normal_mapping -o
// d/crate_diffuse.tga replaced the model's own texture with the render).
TEST(FileIo, AnOutputCannotReplaceAFileTheRunRead) {
    rl_test::TempDir dir;
    const auto input = dir.path() / "texture.tga", link = dir.path() / "link.tga",
               hard = dir.path() / "hard.tga", other = dir.path() / "other.tga";
    rl_test::write_text(input, "texels");
    rl_test::write_text(other, "other");
    std::filesystem::create_symlink(input, link);
    std::filesystem::create_hard_link(input, hard);
    rl::forget_inputs();
    rl::check_output(input);  // not read yet: writable
    rl::read_file(input);
    for (const auto& path : {input, link, hard}) {
        try {
            rl::check_output(path);
            ADD_FAILURE() << path << " was accepted";
        } catch (const rl::FileError& e) {
            EXPECT_NE(std::string(e.what()).find("is a file this run read as an input"),
                      std::string::npos)
                << e.what();
        }
        rl::OutputFiles out;
        EXPECT_THROW(out.stage(path, std::vector<std::uint8_t>{1}), rl::FileError);
    }
    rl::check_output(other);  // a file not read stays writable
    EXPECT_EQ(rl::read_file(input), (std::vector<std::uint8_t>{'t', 'e', 'x', 'e', 'l', 's'}));
    rl::forget_inputs();
}

// Two outputs of one run naming one file, by the same name, another
// spelling, or a link, are refused before any work (issue 17: 03_zbuffer -o
// z.tga --depth-out z.tga succeeded and lost one image).
TEST(FileIo, TwoOutputsCannotNameTheSameFile) {
    rl_test::TempDir dir;
    const auto a = dir.path() / "a.tga", existing = dir.path() / "existing.tga",
               link = dir.path() / "link.tga";
    rl_test::write_text(existing, "old");
    std::filesystem::create_symlink(existing, link);
    for (const auto& [first, second] :
         {std::pair{a, a}, std::pair{a, dir.path() / "." / "a.tga"}, std::pair{existing, link}}) {
        rl::OutputFiles out;
        out.check(first);
        EXPECT_THROW(out.check(second), rl::FileError) << first << " and " << second;
    }
    rl::OutputFiles staged;  // staged without checking first: refused at the second stage
    staged.stage(existing, std::vector<std::uint8_t>{1});
    EXPECT_THROW(staged.stage(link, std::vector<std::uint8_t>{2}), rl::FileError);
    rl::OutputFiles two;  // distinct files are fine, each checked and then staged
    two.check(a);
    two.check(existing);
    two.stage(a, std::vector<std::uint8_t>{1});
    two.stage(existing, std::vector<std::uint8_t>{2});
    two.commit();
    rl::forget_inputs();
    EXPECT_EQ(rl::read_file(existing), (std::vector<std::uint8_t>{2}));
    rl::forget_inputs();
}

// A link to a file that does not exist yet is that file: `ln -s f.tga
// l.tga; 03_zbuffer -o f.tga --depth-out l.tga` would write both images to
// f.tga and keep one. Also through a chain of links, and staged without check.
TEST(FileIo, ALinkToAFileNotYetMadeIsThatFile) {
    rl_test::TempDir dir;
    const auto file = dir.path() / "f.tga", link = dir.path() / "l.tga",
               chain = dir.path() / "chain.tga";
    std::filesystem::create_symlink("f.tga", link);  // dangling, relative
    std::filesystem::create_symlink(link, chain);
    EXPECT_TRUE(rl::same_file(file, link));
    EXPECT_TRUE(rl::same_file(chain, file));
    EXPECT_FALSE(rl::same_file(file, dir.path() / "g.tga"));
    rl::OutputFiles out;
    out.check(file);
    EXPECT_THROW(out.check(link), rl::FileError);
    rl::OutputFiles staged;
    staged.stage(chain, std::vector<std::uint8_t>{1});
    EXPECT_THROW(staged.stage(file, std::vector<std::uint8_t>{2}), rl::FileError);
}

// The Python module saves from several threads at once (Result.save releases
// the GIL). Each write must land whole, in its own file, with no temporary
// left; under ThreadSanitizer (the tsan preset runs this test) the shared
// random generator behind the temporaries' names and the registry of pending
// temporaries were reported as data races.
TEST(FileIo, ThreadsSavingAtOnceEachWriteTheirWholeFile) {
    rl_test::TempDir dir;
    constexpr int kThreads = 8, kWrites = 40;
    // Distinct contents, large enough that a mix of two would show.
    const auto content = [](int thread, int write) {
        std::vector<std::uint8_t> bytes(4096 + static_cast<std::size_t>(thread * 97 + write));
        for (std::size_t i = 0; i < bytes.size(); ++i)
            bytes[i] = static_cast<std::uint8_t>(thread * 31 + write * 7 + static_cast<int>(i));
        return bytes;
    };
    const auto file = [&](int thread, int write) {
        char name[32];
        std::snprintf(name, sizeof name, "t%d_%d.bin", thread, write);
        return dir.path() / name;
    };
    std::atomic<int> ready{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            ++ready;
            while (ready.load() < kThreads) std::this_thread::yield();  // all start together
            for (int w = 0; w < kWrites; ++w) {
                rl::write_file_atomically(file(t, w), content(t, w));
                rl::write_file_atomically(dir.path() / "shared.bin", content(t, w));
            }
        });
    for (std::thread& t : threads) t.join();
    for (int t = 0; t < kThreads; ++t)
        for (int w = 0; w < kWrites; ++w)
            ASSERT_EQ(rl::read_file(file(t, w)), content(t, w))
                << "thread " << t << ", write " << w;
    // The shared file is one writer's last write, whole.
    const std::vector<std::uint8_t> shared = rl::read_file(dir.path() / "shared.bin");
    bool whole = false;
    for (int t = 0; t < kThreads; ++t) whole |= shared == content(t, kWrites - 1);
    EXPECT_TRUE(whole);
    EXPECT_EQ(entries(dir.path()), static_cast<std::size_t>(kThreads * kWrites + 1));
    rl::forget_inputs();  // the files read back go with the folder; their inodes may return
}

TEST(FileIoDeathTest, AKilledWriteLeavesNoTemporary) {
    rl_test::TempDir dir;
    const auto path = dir.path() / "out.tga";
    EXPECT_EXIT(
        {
            rl::OutputFiles out;
            const std::vector<std::uint8_t> bytes(1000, 1);
            out.stage(path, bytes);
            std::raise(SIGTERM);
        },
        testing::KilledBySignal(SIGTERM), "");
    EXPECT_EQ(entries(dir.path()), 0u);
}

// Temporaries staged by several threads at once each get a slot of their
// own in the registry the signal handler reads: a signal removes them all.
TEST(FileIoDeathTest, TemporariesStagedByThreadsAtOnceAllGoOnASignal) {
    rl_test::TempDir dir;
    EXPECT_EXIT(
        {
            constexpr int kThreads = 8;
            std::atomic<int> staged{0};
            std::vector<std::thread> threads;
            for (int t = 0; t < kThreads; ++t)
                threads.emplace_back([&, t] {
                    rl::OutputFiles out;
                    out.stage(dir.path() / ("t" + std::to_string(t) + ".tga"),
                              std::vector<std::uint8_t>(1000, 1));
                    ++staged;
                    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // held
                });
            while (staged.load() < kThreads) std::this_thread::yield();
            std::raise(SIGTERM);
        },
        testing::KilledBySignal(SIGTERM), "");
    EXPECT_EQ(entries(dir.path()), 0u);
}

}  // namespace
