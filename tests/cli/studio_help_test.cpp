// padrob-studio --help and --version print their text without a display (the application
// is a QCoreApplication then: a QApplication aborts without one), and --help is entirely
// in Spanish under es_CL or with --lang es (Padrob's catalogue and Qt's own, qtbase_es).
#include "cli_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

/// No display, and a HOME of its own (no language saved by another run).
std::string noDisplay()
{
    const auto home = std::filesystem::temp_directory_path() / ("padrob_studio_help_" + std::to_string(::getpid()));
    std::filesystem::create_directories(home);
    return "-u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM HOME='" + home.string() + "' XDG_CONFIG_HOME='" +
           home.string() + "' ";
}

test::CliRun studio(const std::string& env, const std::string& args) { return test::runWith(PADROB_STUDIO, env, args); }

/// The texts of a --help a person reads: each line without its indentation and, for an
/// option's line, without the option's column; only those of two words or more (not a
/// lone metavariable or name).
std::vector<std::string> sentences(const std::string& help)
{
    std::vector<std::string> out;
    for (std::string line : test::lines(help)) {
        line.erase(0, line.find_first_not_of(' '));
        if (line.rfind('-', 0) == 0) {
            const std::size_t gap = line.find("  ");
            line = gap == std::string::npos ? "" : line.substr(line.find_first_not_of(' ', gap));
        }
        if (line.find(' ') != std::string::npos) out.push_back(line);
    }
    return out;
}

}  // namespace

TEST(StudioHelp, VersionWithoutADisplay)
{
    const test::CliRun r = studio(noDisplay() + test::kCLocale, "--version");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "padrob-studio " PADROB_VERSION "\n") << r.err;
}

TEST(StudioHelp, HelpWithoutADisplayInEnglishAndEntirelyInSpanish)
{
    const test::CliRun en = studio(noDisplay() + test::kCLocale, "--help");
    ASSERT_EQ(en.status, 0) << en.err;
    EXPECT_EQ(en.out.rfind("Usage: ", 0), 0u) << en.out;
    EXPECT_NE(en.out.find("--screenshot <FILE>"), std::string::npos) << en.out;
    const std::vector<std::string> english = sentences(en.out);
    ASSERT_GT(english.size(), 20u) << en.out;
    for (const std::string& env : {std::string("LC_ALL=es_CL.UTF-8 LANG=es_CL.UTF-8"), std::string(test::kCLocale)}) {
        const test::CliRun es = studio(noDisplay() + env, env == test::kCLocale ? "--lang es --help" : "--help");
        ASSERT_EQ(es.status, 0) << env << ": " << es.err;
        EXPECT_EQ(es.out.rfind("Uso: ", 0), 0u) << env << ":\n" << es.out;
        EXPECT_NE(es.out.find("Opciones:"), std::string::npos) << env << ":\n" << es.out;
        // no sentence of the English help is left in the Spanish one
        for (const std::string& s : english) EXPECT_EQ(es.out.find(s), std::string::npos) << env << ": '" << s << "'";
    }
}
