#include "solver/pipeline.h"

#include "solver/compile/compile.h"
#include "solver/core/text_file.h"
#include "solver/spec/validate.h"
#include "solver/parse/parser.h"

#include <cstdint>
#include <cstring>
#include <filesystem>

namespace solver {

namespace {

/// Length of the valid UTF-8 sequence at s[i], or 0 when it is not valid.
std::size_t utf8SequenceLength(std::string_view s, std::size_t i)
{
    const auto b0 = static_cast<unsigned char>(s[i]);
    if (b0 < 0x80) return 1;
    std::size_t len = 0;
    unsigned min = 0;
    if ((b0 & 0xE0) == 0xC0) { len = 2; min = 0x80; }
    else if ((b0 & 0xF0) == 0xE0) { len = 3; min = 0x800; }
    else if ((b0 & 0xF8) == 0xF0) { len = 4; min = 0x10000; }
    else return 0;
    if (i + len > s.size()) return 0;
    unsigned cp = b0 & (0x7F >> len);
    for (std::size_t k = 1; k < len; ++k) {
        const auto b = static_cast<unsigned char>(s[i + k]);
        if ((b & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (b & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return len;
}

/// Position (line, column in characters) of byte `at`, in text that is valid up to `at`.
SourcePos positionOf(std::string_view s, std::size_t at)
{
    SourcePos p{1, 1};
    for (std::size_t i = 0; i < at && i < s.size(); ++i) {
        if (s[i] == '\n') { ++p.line; p.column = 1; }
        else if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) ++p.column;
    }
    return p;
}

/// Makes the text valid UTF-8. Returns false (with an error) for binary data.
/// Text that is not UTF-8 is read as Latin-1 (ISO 8859-1), with a warning.
bool decode(std::string_view raw, std::string& out, Diagnostics& diags)
{
    // one pass finds what the checks below need: the first NUL byte, the control
    // characters in the first 64 KiB, the first byte that is not valid UTF-8
    const std::size_t n = raw.size();
    const std::size_t sample = std::min<std::size_t>(n, 1 << 16);
    std::size_t controls = 0;
    std::size_t firstNul = std::string_view::npos;
    std::size_t firstBad = std::string_view::npos;
    for (std::size_t i = 0; i < n;) {
        // eight printable ASCII characters at once (no byte below 0x20 or from 0x80 on)
        if (i + 8 <= n) {
            std::uint64_t w;
            std::memcpy(&w, raw.data() + i, 8);
            constexpr std::uint64_t kHigh = 0x8080808080808080ull, kSpace = 0x2020202020202020ull;
            if (((w | ((w - kSpace) & ~w)) & kHigh) == 0) {
                i += 8;
                continue;
            }
        }
        const auto c = static_cast<unsigned char>(raw[i]);
        if (c < 0x80) {
            if (c == 0) {
                firstNul = i;
                break;
            }
            if (i < sample && c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v') ++controls;
            ++i;
            continue;
        }
        if (firstBad == std::string_view::npos) {
            const std::size_t len = utf8SequenceLength(raw, i);
            if (len > 0) {
                i += len;  // a valid sequence: bytes from 0x80 on, neither NUL nor control characters
                continue;
            }
            firstBad = i;
        }
        ++i;
    }
    // binary: NUL bytes, or many control characters
    if (firstNul != std::string_view::npos) {
        diags.error("binary-file", positionOf(raw, firstNul),
                    trText("Diagnostics", "this is not a text file (it contains a NUL byte here)"),
                    trText("Diagnostics", "a model is a text file (.pad); open the model, not a mesh, image or archive"));
        return false;
    }
    // (a few stray control characters in a short text are the lexer's to report, with
    // their positions; only many of them make a file binary)
    if (sample > 0 && controls >= 4 && controls * 20 > sample) {
        diags.error("binary-file", {1, 1},
                    trText("Diagnostics", "this is not a text file (%1 control characters in its first %2 bytes)")
                        .with(std::to_string(controls))
                        .with(std::to_string(sample)),
                    trText("Diagnostics", "a model is a text file (.pad); open the model, not a mesh, image or archive"));
        return false;
    }
    if (firstBad == std::string_view::npos) {
        out.assign(raw);
        return true;
    }
    // the position in the text as read, Latin-1: one byte, one character (like the
    // columns of every later diagnostic of this file)
    SourcePos bad{1, 1};
    for (std::size_t i = 0; i < firstBad; ++i) {
        if (raw[i] == '\n') { ++bad.line; bad.column = 1; }
        else ++bad.column;
    }
    char byte[3];
    std::snprintf(byte, sizeof byte, "%02X", static_cast<unsigned char>(raw[firstBad]));
    diags.warning("not-utf8", bad,
                  trText("Diagnostics", "the file is not UTF-8 (byte 0x%1 here); it was read as Latin-1 (ISO 8859-1)")
                      .with(byte),
                  trText("Diagnostics", "save the file as UTF-8 so every editor shows its accents the same way"));
    out.clear();
    out.reserve(raw.size() + raw.size() / 8);
    for (char ch : raw) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x80) {
            out += ch;
        } else {
            out += static_cast<char>(0xC0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3F));
        }
    }
    return true;
}

std::string baseDirOf(const std::string& file)
{
    std::string baseDir;
    if (!file.empty() && file[0] != '<') baseDir = std::filesystem::path(file).parent_path().string();
    return baseDir.empty() ? std::string(".") : baseDir;
}

/// validate and compile `m.spec`, into m (whose diagnostics may hold the parser's)
void checkAndCompile(CompiledModel& m, const std::string& baseDir, const ModelSpec* scene = nullptr)
{
    validateModel(m.spec, m.diagnostics, baseDir);
    // the checks of the whole geometry need every statement right
    if (!m.diagnostics.hasErrors()) {
        // (set only when compiling added no error, and there were none before it)
        CompileResult compiled = compileModel(m.spec, m.diagnostics, scene);
        m.topology = std::move(compiled.topology);
        m.model = std::move(compiled.model);
    }
    m.diagnostics.sortByPosition();
}

}  // namespace

CompiledModel compileText(std::string_view text, const std::string& file)
{
    Diagnostics pre(file);
    std::string decoded;
    if (!decode(text, decoded, pre)) {
        CompiledModel m;
        m.spec.file = file;
        m.diagnostics = std::move(pre);
        return m;
    }
    CompiledModel m;
    m.diagnostics.setFile(file);
    m.spec = parse::parseModel(decoded, m.diagnostics);
    m.spec.file = file;
    checkAndCompile(m, baseDirOf(file));
    if (!pre.empty()) {
        pre.append(m.diagnostics);
        m.diagnostics = std::move(pre);
        m.diagnostics.sortByPosition();  // the not-utf8 warning among the others, in line order
    }
    return m;
}

CompiledModel compileFile(const std::string& path)
{
    Diagnostics diags(path);
    std::optional<std::string> text =
        readTextFile(path, kMaxModelFileBytes, trText("Diagnostics", "a model file"), ".pad",
                     trText("Diagnostics", "a model is a short text; put meshes in their own files (G … MESH \"file\")"),
                     diags);
    if (!text) {
        CompiledModel m;
        m.spec.file = path;
        m.diagnostics = std::move(diags);
        return m;
    }
    return compileText(*text, path);
}

CompiledModel compileSpec(ModelSpec spec, const ModelSpec* scene)
{
    CompiledModel m;
    m.diagnostics.setFile(spec.file);
    m.spec = std::move(spec);
    checkAndCompile(m, baseDirOf(m.spec.file), scene);
    return m;
}

}  // namespace solver
