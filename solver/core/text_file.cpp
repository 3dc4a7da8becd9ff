#include "solver/core/text_file.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>

namespace solver {

std::optional<std::string> readTextFile(const std::string& path, std::uintmax_t maxBytes, const Text& fileKind,
                                        const std::string& extension, const Text& tooLargeHint,
                                        Diagnostics& diags)
{
    namespace fs = std::filesystem;
    auto fail = [&](Text message, Text hint) {
        Diagnostic& d = diags.error("io-error", {}, std::move(message), std::move(hint));
        d.file = path;
        return std::nullopt;
    };
    const Text giveThePath = trText("Diagnostics", "give the path of a %1 file").with(extension);
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) return fail(trText("Diagnostics", "no such file"), trText("Diagnostics", "check the path"));
    if (fs::is_directory(st)) return fail(trText("Diagnostics", "this is a folder, not %1").with(fileKind), giveThePath);
    if (!fs::is_regular_file(st)) return fail(trText("Diagnostics", "this is not a regular file"), giveThePath);
    auto tooLarge = [&](std::uintmax_t size) {
        // the size in MB rounded up to a tenth, so that a file just over the limit does
        // not read "16 MB; the limit is 16 MB"
        const auto tenths = (size * 10 + 1024 * 1024 - 1) / (1024 * 1024);
        return fail(trText("Diagnostics", "the file is too large for %1 (%2 MB; the limit is %3 MB)")
                        .with(fileKind)
                        .with(std::to_string(tenths / 10) + "." + std::to_string(tenths % 10))
                        .with(std::to_string(maxBytes / (1024 * 1024))),
                    tooLargeHint);
    };
    const auto size = fs::file_size(path, ec);
    if (!ec && size > maxBytes) return tooLarge(size);
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return fail(trText("Diagnostics", "cannot be read (permission denied?)"),
                    trText("Diagnostics", "check the file's permissions"));
    }
    // at most maxBytes + 1, whatever the size said: a file growing while it is read (or
    // one whose size the system does not know) cannot take the memory
    std::string text;
    std::array<char, 1 << 16> chunk{};
    while (in && text.size() <= maxBytes) {
        in.read(chunk.data(), static_cast<std::streamsize>(std::min<std::uintmax_t>(chunk.size(), maxBytes + 1 - text.size())));
        text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) {
        return fail(trText("Diagnostics", "reading failed"), trText("Diagnostics", "check the disk and the file's permissions"));
    }
    if (text.size() > maxBytes) return tooLarge(text.size());
    return text;
}

}  // namespace solver
