// Whole-file reads and all-or-nothing writes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace rl {

// Every I/O failure in rasterlab is reported as a FileError whose message
// starts with the file's path.
class FileError : public std::runtime_error {
  public:
    FileError(const std::filesystem::path& path, const std::string& problem)
        : std::runtime_error(path.string() + ": " + problem) {}
};

std::vector<std::uint8_t> read_file(const std::filesystem::path& path);

// Writes to a temporary file beside `path`, then renames it over `path`, so
// readers see either the old file or the complete new one, never half of it.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

}  // namespace rl
