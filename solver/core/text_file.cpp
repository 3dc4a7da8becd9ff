#include "solver/core/text_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace solver {

std::optional<std::string> readTextFile(const std::string& path, std::uintmax_t maxBytes, const std::string& kind,
                                        const std::string& extension, const std::string& tooLargeHint,
                                        Diagnostics& diags)
{
    namespace fs = std::filesystem;
    auto fail = [&](std::string message, std::string hint) {
        Diagnostic& d = diags.error("io-error", {}, std::move(message), std::move(hint));
        d.file = path;
        return std::nullopt;
    };
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) return fail("no such file", "check the path");
    if (fs::is_directory(st)) return fail("this is a folder, not " + kind + " file", "give the path of a " + extension + " file");
    if (!fs::is_regular_file(st)) return fail("this is not a regular file", "give the path of a " + extension + " file");
    const auto size = fs::file_size(path, ec);
    if (!ec && size > maxBytes) {
        // the size in MB rounded up to a tenth, so that a file just over the limit does
        // not read "16 MB; the limit is 16 MB"
        const auto tenths = (size * 10 + 1024 * 1024 - 1) / (1024 * 1024);
        return fail("the file is too large for " + kind + " file (" + std::to_string(tenths / 10) + "." +
                        std::to_string(tenths % 10) + " MB; the limit is " + std::to_string(maxBytes / (1024 * 1024)) +
                        " MB)",
                    tooLargeHint);
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail("cannot be read (permission denied?)", "check the file's permissions");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) return fail("reading failed", "check the disk and the file's permissions");
    return std::move(ss).str();
}

}  // namespace solver
