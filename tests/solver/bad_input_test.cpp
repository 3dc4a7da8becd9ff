// What the loader does with input that is not a model, or not quite text: binary
// junk, huge files and lines, non-finite and huge numbers, missing files and
// folders, Latin-1, a byte order mark and CRLF line endings.
//
// Temporary files live in a fresh folder under temp_directory_path() (temp_dir.h).

#include "solver/pipeline.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <chrono>
#include <climits>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

using namespace solver;
namespace fs = std::filesystem;

namespace {

std::string listing(const Diagnostics& diags)
{
    std::string s;
    for (const Diagnostic& d : diags) s += "  " + d.code + " | " + d.format() + "\n";
    return s.empty() ? "  (none)\n" : s;
}

/// A scratch folder for one test's files.
struct TempDir : solver::test::TempDir {
    TempDir() : solver::test::TempDir("bad_input_test") {}
};

double secondsSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// A valid model: body 1 on a revolute joint to ground (4 lines).
const std::string kModel = "B 1 1 1 1 1 NAME \"arm\"\nC 1\nB1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0\n"
                           "B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0\n";

const std::string kBinaryHint = " [a model is a text file (.pad); open the model, not a mesh, image or archive]";

}  // namespace

// ---- binary junk --------------------------------------------------------------------

TEST(BadInput, RandomBytesAreABinaryFile)
{
    std::mt19937 rng(7);
    std::string junk(4096, '\0');
    for (char& c : junk) c = static_cast<char>(rng() & 0xFF);
    const auto nul = junk.find('\0');
    ASSERT_NE(nul, std::string::npos);  // 4096 random bytes hold a NUL (seed 7: several)

    CompiledModel m = compileText(junk, "m.pad");
    ASSERT_EQ(m.diagnostics.size(), 1u) << listing(m.diagnostics);
    const Diagnostic& d = m.diagnostics.items()[0];
    EXPECT_EQ(d.code, "binary-file");
    EXPECT_EQ(d.severity, Severity::Error);
    EXPECT_EQ(d.message, "this is not a text file (it contains a NUL byte here)");
    EXPECT_EQ(d.pos.line, 1 + static_cast<int>(std::count(junk.begin(), junk.begin() + static_cast<long>(nul), '\n')));
    EXPECT_GE(d.pos.column, 1);
    EXPECT_FALSE(m.ok());
    EXPECT_FALSE(m.topology.has_value());
    EXPECT_TRUE(m.spec.bodies.empty());
}

TEST(BadInput, RandomBytesWithoutNulAreABinaryFile)
{
    std::mt19937 rng(8);
    std::string junk(4096, '\0');
    for (char& c : junk) c = static_cast<char>(1 + rng() % 255);
    std::size_t controls = 0;
    for (char c : junk) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v') ++controls;
    }
    ASSERT_GT(controls * 20, junk.size());  // more than 5 %

    CompiledModel m = compileText(junk, "m.pad");
    ASSERT_EQ(m.diagnostics.size(), 1u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].format(), "m.pad:1:1: error: this is not a text file (" +
                                                     std::to_string(controls) +
                                                     " control characters in its first 4096 bytes)" + kBinaryHint);
    EXPECT_FALSE(m.topology.has_value());
}

TEST(BadInput, PngImageIsABinaryFile)
{
    // a PNG's signature and the start of its IHDR chunk; the first NUL is byte 8, at
    // the start of line 3 (after "\x89PNG\r\n" and "\x1a\n")
    static const char kPng[] = "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\x01\0\0\0\x01\0\x08\x06\0\0\0";
    const std::string png(kPng, sizeof kPng - 1);
    ASSERT_EQ(png.size(), 29u);
    TempDir dir;
    const std::string file = dir.write("picture.png", png);
    CompiledModel m = compileFile(file);
    ASSERT_EQ(m.diagnostics.size(), 1u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].code, "binary-file");
    EXPECT_EQ(m.diagnostics.items()[0].format(),
              file + ":3:1: error: this is not a text file (it contains a NUL byte here)" + kBinaryHint);
    EXPECT_FALSE(m.ok());
    EXPECT_FALSE(m.topology.has_value());
}

TEST(BadInput, AFewControlCharactersAreNotABinaryFile)
{
    // one stray control character in a short model is reported where it is
    CompiledModel m = compileText("B 1 1 1 1 1\x1B\n", "m.pad");
    ASSERT_EQ(m.diagnostics.size(), 1u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].format(),
              "m.pad:1:12: error: unexpected control character (code 27) [delete it; a model file is plain text]");
}

// ---- size limits ----------------------------------------------------------------------

TEST(BadInput, FileOfSeventeenMegabytesIsTooLarge)
{
    TempDir dir;
    const std::string file = dir.write("huge.pad", std::string(17u * 1024u * 1024u, '#'));
    ASSERT_EQ(fs::file_size(file), 17u * 1024u * 1024u);
    CompiledModel m = compileFile(file);
    ASSERT_EQ(m.diagnostics.size(), 1u) << listing(m.diagnostics);
    const Diagnostic& d = m.diagnostics.items()[0];
    EXPECT_EQ(d.code, "io-error");
    EXPECT_EQ(d.pos, (SourcePos{0, 0}));
    EXPECT_EQ(d.format(), file +
                              ": error: the file is too large for a model file (17.0 MB; the limit is 16 MB) [a model is a "
                              "short text; put meshes in their own files (G … MESH \"file\")]");
    EXPECT_FALSE(m.ok());
    EXPECT_FALSE(m.topology.has_value());
}

TEST(BadInput, FileJustOverTheLimitSaysByHowMuch)
{
    TempDir dir;
    const std::string file = dir.write("big.pad", std::string(kMaxModelFileBytes + 1, '#'));
    CompiledModel m = compileFile(file);
    ASSERT_EQ(m.diagnostics.size(), 1u) << listing(m.diagnostics);
    // not "16 MB; the limit is 16 MB"
    EXPECT_EQ(m.diagnostics.items()[0].message, "the file is too large for a model file (16.1 MB; the limit is 16 MB)");
}

TEST(BadInput, FileAtTheLimitIsRead)
{
    // a model followed by comment lines, exactly kMaxModelFileBytes long
    std::string text = kModel;
    const std::string comment = "// " + std::string(76, '-') + "\n";
    while (text.size() + comment.size() <= kMaxModelFileBytes) text += comment;
    text += std::string(kMaxModelFileBytes - text.size() - 1, ' ') + "\n";
    ASSERT_EQ(text.size(), kMaxModelFileBytes);
    TempDir dir;
    const std::string file = dir.write("limit.pad", text);
    const auto t0 = std::chrono::steady_clock::now();
    CompiledModel m = compileFile(file);
    EXPECT_LT(secondsSince(t0), 10.0);
    EXPECT_TRUE(m.diagnostics.empty()) << listing(m.diagnostics);
    EXPECT_TRUE(m.topology.has_value());
}

TEST(BadInput, LineOfAMillionTokensIsFast)
{
    // GRAVITY, then 491,000 surplus numbers and a word at the very end: the word's
    // column must be right, and the time linear
    std::string line = "GRAVITY 0 0 -9.81";
    for (int k = 0; k < 491000; ++k) line += " 1";
    line += " x";
    ASSERT_GT(line.size(), 980000u);
    const auto t0 = std::chrono::steady_clock::now();
    CompiledModel m = compileText(line + "\n", "m.pad");
    EXPECT_LT(secondsSince(t0), 2.0);
    ASSERT_EQ(m.diagnostics.size(), 2u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].format(), "m.pad:1:19: error: GRAVITY: unexpected number 1 [remove it]");
    EXPECT_EQ(m.diagnostics.items()[1].format(), "m.pad:1:" + std::to_string(line.size()) +
                                                     ": error: GRAVITY: 'x' is not an option of GRAVITY [remove it]");
}

TEST(BadInput, LineOfAMillionCharactersCountsCharacters)
{
    // a name of a million 'ñ' (two bytes each), then a bad CG: columns are characters
    std::string name;
    for (int k = 0; k < 1000000; ++k) name += "ñ";
    const std::string line = "B 1 NAME \"" + name + "\" CG 0 x 0";
    const auto t0 = std::chrono::steady_clock::now();
    CompiledModel m = compileText(line, "m.pad");
    EXPECT_LT(secondsSince(t0), 2.0);
    ASSERT_EQ(m.diagnostics.size(), 1u) << listing(m.diagnostics);
    // `B 1 NAME "` is 10 characters, the name 1,000,000, then `" CG 0 ` (7): x is 1,000,018
    EXPECT_EQ(m.diagnostics.items()[0].format(),
              "m.pad:1:1000018: error: body 1: 'x' is not a number [numbers look like 12, -0.5, .2 or 1e-3]");
    ASSERT_EQ(m.spec.bodies.size(), 1u);
    EXPECT_EQ(m.spec.bodies[0].name.size(), 2000000u);
}

TEST(BadInput, ManyErrorsAreCappedNotStored)
{
    std::string text;
    for (int k = 0; k < 20000; ++k) text += "x\n";
    CompiledModel m = compileText(text, "m.pad");
    EXPECT_EQ(m.diagnostics.errorCount(), 20000u);
    ASSERT_EQ(m.diagnostics.size(), Diagnostics::kDefaultLimit + 1);
    EXPECT_TRUE(m.diagnostics.truncated());
    EXPECT_EQ(m.diagnostics.items()[0].format(),
              "m.pad:1:1: error: unknown keyword 'x' [did you mean 'B'?]");
    EXPECT_EQ(m.diagnostics.items().back().code, "too-many-diagnostics");
    EXPECT_EQ(m.diagnostics.items().back().severity, Severity::Note);
    EXPECT_FALSE(m.ok());
}

// ---- numbers ---------------------------------------------------------------------------

TEST(BadInput, NanAndInfinityLiterals)
{
    CompiledModel m = compileText(R"pad(GRAVITY nan INF -Infinity
B 1 10 NaN 1 1
C 1 QI +inf
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 -nan 1 0
B nan
)pad",
                                  "m.pad");
    const std::string hint = " [write a finite value; NaN and infinity are not allowed]";
    ASSERT_EQ(m.diagnostics.size(), 7u) << listing(m.diagnostics);
    const auto& d = m.diagnostics.items();
    EXPECT_EQ(d[0].format(), "m.pad:1:9: error: GRAVITY: 'nan' is not a finite number" + hint);
    EXPECT_EQ(d[1].format(), "m.pad:1:13: error: GRAVITY: 'INF' is not a finite number" + hint);
    EXPECT_EQ(d[2].format(), "m.pad:1:17: error: GRAVITY: '-Infinity' is not a finite number" + hint);
    EXPECT_EQ(d[3].format(), "m.pad:2:8: error: body 1: 'NaN' is not a finite number" + hint);
    EXPECT_EQ(d[4].format(), "m.pad:3:8: error: joint 1: '+inf' is not a finite number" + hint);
    EXPECT_EQ(d[5].format(), "m.pad:5:27: error: joint 1, B2: '-nan' is not a finite number" + hint);
    EXPECT_EQ(d[6].format(), "m.pad:6:3: error: body: 'nan' is not a finite number" + hint);
    for (const Diagnostic& x : d) EXPECT_EQ(x.code, "not-finite");
    EXPECT_FALSE(m.topology.has_value());
}

TEST(BadInput, AMassOrInertiaBeyondAnyMachineIsAnError)
{
    // summed along the tree they would overflow: the closed loop's SVD crashed on them
    std::ifstream in(std::string(PADROB_SOURCE_DIR) + "/models/slider_crank.pad");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string piston = "B 3 0.5 0.000225 ";
    ASSERT_NE(text.find(piston), std::string::npos);
    std::string huge = text;
    huge.replace(huge.find(piston), piston.size(), "B 3 0.5 1.7976931348623157e308 ");
    CompiledModel m = compileText(huge, "m.pad");
    ASSERT_FALSE(m.ok());
    ASSERT_EQ(m.diagnostics.errorCount(), 1u) << listing(m.diagnostics);
    const Diagnostic& d = m.diagnostics.items().front();
    EXPECT_EQ(d.code, "too-large");
    EXPECT_EQ(d.format(), "m.pad:44:9: error: body 3 (piston)'s inertia 1.79769e+308 kg m² is beyond any machine's (at most 1e+18 kg "
                          "m²) [check the units: moments and products of inertia are in kg m²]");
    std::string heavy = text;
    heavy.replace(heavy.find(piston), piston.size(), "B 3 5e12 0.000225 ");
    m = compileText(heavy, "m.pad");
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.diagnostics.items().front().code, "too-large");
    EXPECT_NE(m.diagnostics.items().front().format().find("m.pad:44:5: error: body 3 (piston)'s mass 5e+12 kg"), std::string::npos)
        << listing(m.diagnostics);
}

TEST(BadInput, HugeAndTinyNumbers)
{
    CompiledModel m = compileText(R"pad(GRAVITY 1e308 -1.7976931348623157e308 1e-400
B 1 1e309 1 1 1
B 2 1 1 1 -2e308
)pad",
                                  "m.pad");
    ASSERT_EQ(m.diagnostics.size(), 2u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].format(),
              "m.pad:2:5: error: body 1: 1e309 is out of range [a number must lie within ±1.7e308]");
    EXPECT_EQ(m.diagnostics.items()[1].format(),
              "m.pad:3:11: error: body 2: -2e308 is out of range [a number must lie within ±1.7e308]");
    EXPECT_EQ(m.spec.gravity, Eigen::Vector3d(1e308, -1.7976931348623157e308, 0.0));  // 1e-400 underflows to 0
}

TEST(BadInput, IdsNearIntMax)
{
    CompiledModel ok = compileText(R"pad(B 2147483646 1 1 1 1
B +2147483647 1 1 1 1
C 02147483647
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 2147483646 P2 0 0 0 A2 0 0 1 R2 0 1 0
C 2147483646
B1 2147483646 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 2147483647 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
                                   "m.pad");
    EXPECT_TRUE(ok.diagnostics.empty()) << listing(ok.diagnostics);
    ASSERT_EQ(ok.spec.bodies.size(), 2u);
    EXPECT_EQ(ok.spec.bodies[0].id, INT_MAX - 1);
    EXPECT_EQ(ok.spec.bodies[1].id, INT_MAX);
    ASSERT_EQ(ok.spec.joints.size(), 2u);
    EXPECT_EQ(ok.spec.joints[0].id, INT_MAX);
    EXPECT_EQ(ok.spec.joints[1].side2.body, INT_MAX);
    ASSERT_TRUE(ok.topology.has_value());
    EXPECT_EQ(ok.topology->dof, 2);

    CompiledModel bad = compileText(R"pad(B 2147483648
B -2147483648
B 2147483647.0
B 2.147483647e9
B 18446744073709551616
)pad",
                                    "m.pad");
    const std::string hint = " [ids are whole numbers 0, 1, 2, …]";
    ASSERT_EQ(bad.diagnostics.size(), 5u) << listing(bad.diagnostics);
    const auto& d = bad.diagnostics.items();
    EXPECT_EQ(d[0].format(),
              "m.pad:1:3: error: body: the body id 2147483648 is too large [ids go from 0 to 2147483647]");
    EXPECT_EQ(d[1].format(), "m.pad:2:3: error: body: the body id cannot be negative (-2147483648)" + hint);
    EXPECT_EQ(d[2].format(), "m.pad:3:3: error: body: the body id must be a whole number, not 2147483647.0" + hint);
    EXPECT_EQ(d[3].format(), "m.pad:4:3: error: body: the body id must be a whole number, not 2.147483647e9" + hint);
    EXPECT_EQ(d[4].format(),
              "m.pad:5:3: error: body: the body id 18446744073709551616 is too large [ids go from 0 to 2147483647]");
    for (const Diagnostic& x : d) EXPECT_EQ(x.code, "bad-id");
    EXPECT_TRUE(bad.spec.bodies.empty());
}

// ---- files that cannot be read ---------------------------------------------------------

TEST(BadInput, MissingFile)
{
    TempDir dir;
    const std::string file = dir.path("does-not-exist.pad");
    CompiledModel m = compileFile(file);
    ASSERT_EQ(m.diagnostics.size(), 1u);
    EXPECT_EQ(m.diagnostics.items()[0].code, "io-error");
    EXPECT_EQ(m.diagnostics.items()[0].pos, (SourcePos{0, 0}));
    EXPECT_EQ(m.diagnostics.items()[0].format(), file + ": error: no such file [check the path]");
    EXPECT_FALSE(m.ok());
    EXPECT_FALSE(m.topology.has_value());
}

TEST(BadInput, DirectoryIsNotAModel)
{
    TempDir dir;
    fs::create_directories(dir.path("models.pad"));
    CompiledModel m = compileFile(dir.path("models.pad"));
    ASSERT_EQ(m.diagnostics.size(), 1u);
    EXPECT_EQ(m.diagnostics.items()[0].code, "io-error");
    EXPECT_EQ(m.diagnostics.items()[0].format(),
              dir.path("models.pad") + ": error: this is a folder, not a model file [give the path of a .pad file]");
    EXPECT_FALSE(m.ok());
}

// ---- encodings and line endings ----------------------------------------------------------

TEST(BadInput, Latin1FileLoadsWithAWarning)
{
    // "// Extensión de la muñeca" and a name, in ISO 8859-1 (ó = 0xF3, ñ = 0xF1)
    const std::string text = "// Extensi\xF3n de la mu\xF1" "eca\nB 1 1 1 1 1 NAME \"mu\xF1" "eca\"\nC 1\n"
                             "B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0\nB2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0\n";
    TempDir dir;
    const std::string file = dir.write("latin1.pad", text);
    CompiledModel m = compileFile(file);
    ASSERT_EQ(m.diagnostics.size(), 1u) << listing(m.diagnostics);
    const Diagnostic& d = m.diagnostics.items()[0];
    EXPECT_EQ(d.code, "not-utf8");
    EXPECT_EQ(d.severity, Severity::Warning);
    EXPECT_EQ(d.format(), file +
                              ":1:11: warning: the file is not UTF-8 (byte 0xF3 here); it was read as Latin-1 (ISO "
                              "8859-1) [save the file as UTF-8 so every editor shows its accents the same way]");
    EXPECT_TRUE(m.ok());
    ASSERT_TRUE(m.topology.has_value());
    ASSERT_EQ(m.spec.bodies.size(), 1u);
    EXPECT_EQ(m.spec.bodies[0].name, "muñeca");  // now UTF-8
}

TEST(BadInput, Latin1ColumnsCountOneCharacterPerByte)
{
    // read as Latin-1, every byte is a character: "ñ" in UTF-8 (2 bytes) is "Ã±" here,
    // and the warning's column agrees with the error's on the same line
    const std::string text = "B 1 NAME \"\xC3\xB1\xF1\" 4,5\n";
    CompiledModel m = compileText(text, "m.pad");
    ASSERT_EQ(m.diagnostics.size(), 2u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].code, "not-utf8");
    EXPECT_EQ(m.diagnostics.items()[0].pos, (SourcePos{1, 13}));
    EXPECT_EQ(m.diagnostics.items()[1].format(),
              "m.pad:1:16: error: body 1: unexpected number 4,5 [remove it, or put an option before it (CG, NAME)]");
    EXPECT_EQ(m.spec.bodies[0].name, "Ã±ñ");
}

TEST(BadInput, Latin1WarningListedInLineOrder)
{
    // an error above the first non-UTF-8 byte is listed first
    CompiledModel m = compileText("GRAVTY 0 0 -9.81\n// mu\xF1" "eca\n", "m.pad");
    ASSERT_EQ(m.diagnostics.size(), 2u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].format(),
              "m.pad:1:1: error: unknown keyword 'GRAVTY' [did you mean 'GRAVITY'?]");
    EXPECT_EQ(m.diagnostics.items()[1].code, "not-utf8");
    EXPECT_EQ(m.diagnostics.items()[1].pos, (SourcePos{2, 6}));
}

TEST(BadInput, ByteOrderMarkAndCrlf)
{
    std::string crlf;
    for (char c : kModel) {
        if (c == '\n') crlf += '\r';
        crlf += c;
    }
    CompiledModel ok = compileText("\xEF\xBB\xBF" + crlf, "m.pad");
    EXPECT_TRUE(ok.diagnostics.empty()) << listing(ok.diagnostics);
    ASSERT_TRUE(ok.topology.has_value());
    EXPECT_EQ(ok.spec.bodies[0].name, "arm");
    EXPECT_EQ(ok.spec.bodies[0].src.pos, (SourcePos{1, 1}));  // the BOM is not a character

    CompiledModel bad = compileText("\xEF\xBB\xBF" "B 1 1 1 1 x\r\nB 2 1 1 1 4,5\r\nGRAVITY 0 0\r\n", "m.pad");
    ASSERT_EQ(bad.diagnostics.size(), 3u) << listing(bad.diagnostics);
    EXPECT_EQ(bad.diagnostics.items()[0].format(),
              "m.pad:1:11: error: body 1: 'x' is not a number [numbers look like 12, -0.5, .2 or 1e-3]");
    EXPECT_EQ(bad.diagnostics.items()[1].format(),
              "m.pad:2:11: error: body 2: '4,5' is not a number [use '.' as the decimal separator: 4.5]");
    // the end of a CRLF line is before the CR
    EXPECT_EQ(bad.diagnostics.items()[2].format(),
              "m.pad:3:12: error: GRAVITY: GRAVITY needs 3 numbers, only 2 given [write GRAVITY gx gy gz (m/s², z is up)]");
}

TEST(BadInput, EmptyAndBlankFiles)
{
    for (const std::string text : {"", "\n", "   \t\n\r\n// only a comment\n# another\n", "\xEF\xBB\xBF"}) {
        CompiledModel m = compileText(text, "m.pad");
        EXPECT_TRUE(m.diagnostics.empty()) << listing(m.diagnostics);
        EXPECT_TRUE(m.ok());
        EXPECT_TRUE(m.spec.bodies.empty());
    }
}
