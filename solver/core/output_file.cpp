#include "solver/core/output_file.h"

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <fcntl.h>
#include <filesystem>
#include <random>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace solver {

namespace fs = std::filesystem;

namespace {

std::string errnoText(int err) { return std::generic_category().message(err); }

/// A fresh name in the target's folder: ".<name>.<random>.tmp".
fs::path freshName(const fs::path& target)
{
    static thread_local std::mt19937_64 gen{(static_cast<std::uint64_t>(std::random_device{}()) << 32) ^ std::random_device{}()};
    char suffix[24];
    auto [end, ec] = std::to_chars(suffix, suffix + sizeof suffix, gen() & 0xFFFFFFFFFFFFull, 16);
    (void)ec;
    return target.parent_path() / ("." + target.filename().string() + "." + std::string(suffix, end) + ".tmp");
}

fs::path folderOf(const fs::path& target)
{
    return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

}  // namespace

std::optional<Text> outputRefusal(const std::string& target, const std::vector<std::string>& inputs)
{
    if (target.empty()) return trText("Diagnostics", "no output file given");
    std::error_code ec;
    if (fs::is_directory(target, ec)) return trText("Diagnostics", "cannot write %1: it is a folder").with(target);
    for (const std::string& input : inputs) {
        if (input.empty()) continue;
        std::error_code e1, e2, e3;
        // the same file by any path or hard link; two paths to a file not made yet
        const bool same = fs::exists(input, e1) && fs::exists(target, e2)
                              ? fs::equivalent(target, input, e3) && !e3
                              : fs::weakly_canonical(target, e1) == fs::weakly_canonical(input, e2) && !e1 && !e2;
        if (same) {
            return trText("Diagnostics", "cannot write %1: it is %2, which this run reads; give another output file")
                .with(target)
                .with(input);
        }
    }
    return std::nullopt;
}

OutputFile::~OutputFile() { abandon(); }

bool OutputFile::fail(Text message)
{
    if (m_error.empty()) m_error = std::move(message);
    abandon();
    return false;
}

bool OutputFile::open(const std::string& target, const std::vector<std::string>& inputs)
{
    abandon();
    m_error = {};
    m_target = target;
    if (std::optional<Text> refusal = outputRefusal(target, inputs)) return fail(std::move(*refusal));
    std::error_code ec;
    const fs::file_status st = fs::status(target, ec);
    if (!ec && fs::exists(st) && !fs::is_regular_file(st)) {
        // a device, a terminal, a FIFO: written into, never replaced
        m_replacing = false;
        errno = 0;
        m_file = std::fopen(target.c_str(), "wb");
        if (!m_file) return fail(trText("Diagnostics", "cannot write %1: %2").with(target).with(errnoText(errno)));
        return true;
    }
    m_replacing = true;
    // a file that replaces another keeps its permissions (a model kept private stays so)
    m_mode = !ec && fs::exists(st) ? static_cast<int>(st.permissions() & fs::perms::mask) : -1;
    // an unnamed file in the target's folder (a rename within one file system replaces
    // the target in one step)
    m_fd = ::open(folderOf(target).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (m_fd >= 0) {
        m_file = ::fdopen(m_fd, "wb");
        if (!m_file) {
            const int err = errno;
            ::close(m_fd);
            m_fd = -1;
            return fail(trText("Diagnostics", "cannot create %1: %2").with(target).with(errnoText(err)));
        }
        return true;
    }
    int err = errno;
    if (err != EOPNOTSUPP && err != EISDIR && err != EINVAL) {
        return fail(trText("Diagnostics", "cannot create %1: %2").with(target).with(errnoText(err)));
    }
    for (int attempt = 0; attempt < 16; ++attempt) {
        const fs::path tmp = freshName(target);
        errno = 0;
        m_file = std::fopen(tmp.c_str(), "wbx");
        if (m_file) {
            m_tmpPath = tmp.string();
            return true;
        }
        err = errno;
        if (err != EEXIST) break;
    }
    return fail(trText("Diagnostics", "cannot create %1: %2").with(target).with(errnoText(err)));
}

bool OutputFile::commit()
{
    if (!m_file) return m_error.empty() ? fail(trText("Diagnostics", "the output was already closed")) : false;
    std::FILE* f = m_file;
    if (std::fflush(f) != 0 || std::ferror(f)) return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(errnoText(errno)));
    if (!m_replacing) {
        m_file = nullptr;
        if (std::fclose(f) != 0) return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(errnoText(errno)));
        return true;
    }
    // on the disk before it takes the target's place (a full disk is found here, not
    // after a power cut)
    if (m_mode >= 0 && ::fchmod(::fileno(f), static_cast<mode_t>(m_mode)) != 0)
        return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(errnoText(errno)));
    if (::fsync(::fileno(f)) != 0) return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(errnoText(errno)));
    // all of it on the disk (a file system that took less than was written says so here)
    struct stat written {};
    const long end = std::ftell(f);
    if (::fstat(::fileno(f), &written) != 0 || end < 0 || written.st_size != static_cast<off_t>(end))
        return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(errnoText(ENOSPC)));
    if (m_fd >= 0) {
        // give the unnamed file a fresh name, then rename that over the target
        const std::string proc = "/proc/self/fd/" + std::to_string(m_fd);
        int err = EEXIST;
        for (int attempt = 0; attempt < 16 && err == EEXIST; ++attempt) {
            const fs::path tmp = freshName(m_target);
            if (::linkat(AT_FDCWD, proc.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) == 0) {
                m_tmpPath = tmp.string();
                err = 0;
            } else {
                err = errno;
            }
        }
        if (err != 0) return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(errnoText(err)));
    }
    m_file = nullptr;
    m_fd = -1;
    if (std::fclose(f) != 0) return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(errnoText(errno)));
    std::error_code ec;
    fs::rename(m_tmpPath, m_target, ec);
    if (ec) return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(ec.message()));
    m_tmpPath.clear();
    // the rename itself on the disk: the folder's entry (a power cut keeps the new file)
    fs::path folder = fs::path(m_target).parent_path();
    if (folder.empty()) folder = ".";
    if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        const int err = ::fsync(dir) == 0 || errno == EINVAL ? 0 : errno;  // (some file systems cannot sync a folder)
        ::close(dir);
        if (err != 0) return fail(trText("Diagnostics", "cannot write %1: %2").with(m_target).with(errnoText(err)));
    }
    return true;
}

void OutputFile::abandon()
{
    if (m_file) std::fclose(m_file);  // (closes m_fd too: an unnamed file vanishes)
    m_file = nullptr;
    m_fd = -1;
    if (!m_tmpPath.empty()) {
        std::error_code ec;
        fs::remove(m_tmpPath, ec);
        m_tmpPath.clear();
    }
}

bool writeWholeFile(const std::string& target, std::string_view text, const std::vector<std::string>& inputs, Text& error)
{
    OutputFile out;
    if (out.open(target, inputs) && std::fwrite(text.data(), 1, text.size(), out.stream()) == text.size() && out.commit()) return true;
    if (out.ok()) {
        // (the write failed: say why, then let the destructor abandon)
        error = trText("Diagnostics", "cannot write %1: %2").with(target).with(errnoText(errno));
        return false;
    }
    error = out.error();
    return false;
}

}  // namespace solver
