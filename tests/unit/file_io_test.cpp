#include <gtest/gtest.h>

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

}  // namespace
