// Whole-file reads with a size cap, and all-or-nothing writes.
//
//   std::vector<std::uint8_t> bytes = rl::read_file("in.tga");   // regular files only
//   rl::OutputFiles out;                 // several outputs, all or nothing:
//   out.check("a.tga"); out.check("b.png");          // before any work is done
//   out.stage("a.tga", bytes_a); out.stage("b.png", bytes_b);
//   out.commit();                        // renames every temporary over its target
//
// The rules (docs/robustness.md): only regular files are read, never more
// than a stated number of bytes; an output is written beside its target and
// renamed over it, so a reader sees the old file or the whole new one; a
// symbolic link is written through to its target; a read-only file, a
// directory or a device is refused, never replaced.
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
        : std::runtime_error((path.empty() ? std::string("'' (an empty path)") : path.string()) +
                             ": " + problem) {}
};

// The most any input file may hold unless a caller says otherwise: 256 MiB,
// well above the largest image the codecs accept (2^28 pixels are refused
// anyway, and a texture of that size would not fit a lesson's memory).
inline constexpr std::uintmax_t kMaxInputBytes = std::uintmax_t{256} << 20;

// Reads a regular file whole. Refuses directories, devices, FIFOs and files
// larger than `max_bytes`, naming the file and the cap. Every file read is
// remembered (by device and inode) for the rest of the run, so that no
// output can replace it: see check_output().
std::vector<std::uint8_t> read_file(const std::filesystem::path& path,
                                    std::uintmax_t max_bytes = kMaxInputBytes);

// Where a write to `path` lands: `path` itself, or the file a symbolic link
// (or a chain of them) points to. Throws FileError for a loop.
std::filesystem::path resolve_output(const std::filesystem::path& path);

// Throws FileError unless `path` can be written without harm: its folder
// exists and is writable, and it is absent or a writable regular file that
// this run has not read (a model's texture, say), through any symbolic or
// hard link.
void check_output(const std::filesystem::path& path);

// The path by which this run read the file at `path` (the same device and
// inode, through symbolic links), or empty if it read no such file.
std::filesystem::path read_as_input(const std::filesystem::path& path);

// Forgets the files read so far: for a test that reads back what it wrote
// and then writes it again, as no program does.
void forget_inputs();

// Whether two paths name one file: the same device and inode when it
// exists, the same absolute path (through symbolic links) when it does not yet.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// A set of outputs written all or nothing. stage() writes a temporary beside
// each target; commit() renames them all over their targets; the destructor
// removes any temporary not committed (also on an exception).
class OutputFiles {
  public:
    OutputFiles() = default;
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;
    ~OutputFiles();

    // check_output(), and refuses a path that names the same file as one
    // checked before (-o z.tga --depth-out z.tga would lose one); stage()
    // refuses one that names the same file as another staged.
    void check(const std::filesystem::path& path);
    void stage(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
    void commit();

  private:
    struct Staged {
        std::filesystem::path requested, target, temporary;
        int pending = -1;  // its slot among the temporaries a signal removes (-1: none)
    };
    void claim(const std::filesystem::path& path);
    std::vector<Staged> staged_;
    std::vector<std::filesystem::path> claimed_;  // every path checked or staged
};

// One output written alone, all or nothing. Threads may write at once (each
// through its own OutputFiles): the temporaries' names and the registry the
// signal handlers read are shared safely.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

// The prefix every temporary file starts with (after a dot), so that one left
// behind by a killed process is recognisable: ".rasterlab-tmp-".
inline constexpr const char* kTemporaryPrefix = ".rasterlab-tmp-";

}  // namespace rl
