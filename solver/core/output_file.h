#pragma once
// Writing a file Padrob produces (a simulation's table, an export, a recorded input log,
// a camera path) without destroying what is not ours:
// - never onto a file the same run reads (the same file by any path or hard link);
// - never onto a folder;
// - a target that exists and is not a regular file (/dev/null, a terminal, a FIFO) is
//   written into as a stream, never replaced by a regular file;
// - otherwise into an unnamed temporary file in the target's folder (Linux O_TMPFILE: a
//   run that dies, even by kill -9, leaves nothing behind), flushed to the disk (fsync)
//   at commit() and only then put in the target's place in one step (linked under a
//   fresh name, renamed over the target), with the permissions of the file it replaces. On a file system without O_TMPFILE a named
//   ".<name>.<random>.tmp" is used, removed on every failure the process sees.

#include "solver/core/diagnostic.h"

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace solver {

/// Why a run that reads `inputs` must not write `target`, or nullopt when it may.
std::optional<Text> outputRefusal(const std::string& target, const std::vector<std::string>& inputs);

class OutputFile {
public:
    OutputFile() = default;
    /// abandon(): the target is left as it was.
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    /// Opens the target for writing (outputRefusal first). False with error().
    bool open(const std::string& target, const std::vector<std::string>& inputs = {});
    /// Where to write, after a successful open() and until commit() or abandon().
    std::FILE* stream() const { return m_file; }
    /// Flushes to the disk and puts the file in the target's place. False with error().
    bool commit();
    /// Closes without touching the target (the temporary file goes).
    void abandon();

    bool ok() const { return m_error.empty(); }
    const Text& error() const { return m_error; }
    const std::string& target() const { return m_target; }
    /// The named temporary file's path while it exists; empty for an unnamed one (the
    /// usual case) and for a stream target.
    const std::string& temporaryPath() const { return m_tmpPath; }
    /// False when the target is written into as a stream (not a regular file).
    bool replacing() const { return m_replacing; }

private:
    bool fail(Text message);

    std::string m_target;
    std::string m_tmpPath;
    std::FILE* m_file = nullptr;
    int m_fd = -1;    // the unnamed temporary's descriptor (O_TMPFILE), else −1
    int m_mode = -1;  // the replaced target's permissions, else −1 (a new file: 0666 & ~umask)
    bool m_replacing = true;
    Text m_error;
};

/// Writes `text` whole to `target` through an OutputFile. False with `error`.
bool writeWholeFile(const std::string& target, std::string_view text, const std::vector<std::string>& inputs, Text& error);

}  // namespace solver
