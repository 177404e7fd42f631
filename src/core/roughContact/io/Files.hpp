// SPDX-License-Identifier: GPL-3.0-or-later
// How the core reads and writes files: the one place of the rules every reader and writer
// follows (docs/cli.md, "Files: what is read and what is written").
//  - A reader opens only a regular file (not a directory, FIFO, device or socket) no larger than
//    the bound of its kind (fileLimits), and says so with the size before it reads a byte; it
//    then reads at most that many bytes, whatever the file does meanwhile.
//  - A writer replaces only a file of its own kind (the caller's `isOwn` on the file's first
//    bytes): any other file at that name is refused and left as it is. It writes a temporary
//    file created exclusively in the target's folder (O_EXCL under a fresh random name: never
//    through a link planted there) and renames it over the target, so that a reader sees the old
//    file or the new one whole, and a failed write leaves nothing behind.
#pragma once

#include <cstdint>
#include <functional>
#include <istream>
#include <memory>
#include <streambuf>
#include <string>

namespace roughContact {

/// The largest file of each kind a reader accepts [bytes]: far above any input the core accepts
/// (Limits.hpp), so that only what is not such a file is refused.
namespace fileLimits {
/// Text tables (profiles, spectra, height matrices): a 4096 x 4096 height map at 64 characters a
/// value (maximumGridPoints).
constexpr std::uint64_t maximumTextBytes = std::uint64_t(1) << 30;
/// An X3P container: the largest map's point list inline and stored uncompressed
/// (x3pLimits::maximumXmlBytes, 64 bytes a point).
constexpr std::uint64_t maximumX3pBytes = std::uint64_t(1) << 30;
/// A .npy array: 4096 x 4096 float64 values and the largest header the reader takes (1 MiB).
constexpr std::uint64_t maximumNpyBytes = (std::uint64_t(8) << 24) + (std::uint64_t(1) << 20) + 16;
/// A boundary-element table: 1000 loads a decade (the most) over 34 decades of load is 34,000
/// lines of about 100 characters, 3.4 MB.
constexpr std::uint64_t maximumTableBytes = std::uint64_t(64) << 20;
/// FFTW wisdom: a few kB a plan.
constexpr std::uint64_t maximumWisdomBytes = std::uint64_t(16) << 20;
} // namespace fileLimits

/// "1.2 GB (1234567890 bytes)"
std::string byteCount(std::uint64_t bytes);

/// A file opened for reading by the rules above: InputError(path, 0, ...) when it is missing,
/// unreadable, not a regular file, or larger than maxBytes (the message gives its size and the
/// bound, `kind` says what the bound is for: "profile", "X3P file"). A stream that ends after
/// maxBytes; a read error sets its badbit.
class InputFile : public std::istream {
public:
    InputFile(const std::string& path, std::uint64_t maxBytes, const std::string& kind);
    ~InputFile() override;
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;
    /// The file's size when it was opened [bytes].
    std::uint64_t size() const noexcept { return size_; }

private:
    class Buffer;
    std::unique_ptr<Buffer> buffer_;
    std::uint64_t size_ = 0;
};

/// The whole of a file (InputFile's rules): for a reader that needs every byte at once (an X3P
/// container, a table whose last line is the digest of the rest).
std::string readWholeFile(const std::string& path, std::uint64_t maxBytes, const std::string& kind);

/// What is at `path` for a writer: nothing, a regular file, or something else (a directory, a
/// FIFO, a device...: described in `what`).
struct ExistingFile {
    enum class Kind { none, regular, other };
    Kind kind = Kind::none;
    std::string what;  ///< "a directory", "a FIFO", ... (Kind::other)
    std::string start; ///< a regular file's first bytes (up to 4096)
};
ExistingFile existingFile(const std::string& path);

/// ParameterError(parameter, ...) unless `path` names nothing or a regular file of the writer's
/// kind (replaceFile's check, for a writer to make before a long computation).
void requireReplaceable(const std::string& path, const std::string& parameter, const std::string& kind,
                        const std::function<bool(const std::string& start)>& isOwn);

/// `contents` written to `path` by the rules above. `isOwn(start)` says whether an existing file
/// whose first bytes are `start` is one of this writer's kind, which it may replace; `kind` names
/// the kind in messages ("boundary-element table"). ParameterError(parameter, ...) when the file
/// is another's (left as it is), when `path` is not a regular file, or when it cannot be written.
void replaceFile(const std::string& path, const std::string& contents, const std::string& parameter,
                 const std::string& kind, const std::function<bool(const std::string& start)>& isOwn);

/// The folder of `path` ("." for a bare name).
std::string folderOf(const std::string& path);

} // namespace roughContact
