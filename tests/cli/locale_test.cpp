// The language of padrob (--lang, the system's locale) and its numbers under a locale with
// a decimal comma: under es_CL.UTF-8 the texts come out in Spanish, every number a script
// reads (CSV, JSON, the values in the texts) keeps the '.', exactly as under C.

#include "tests/common/components.h"
#include "cli_run.h"

#include <gtest/gtest.h>

#include <clocale>
#include <string>

using namespace test;

namespace {

const std::string kSpanish = "LC_ALL=es_CL.UTF-8 LANG=es_CL.UTF-8";

/// True when the C library knows es_CL.UTF-8 (scripts/install-deps.sh generates it).
bool haveSpanishLocale()
{
    const char* old = std::setlocale(LC_ALL, nullptr);
    const std::string saved = old ? old : "C";
    const bool ok = std::setlocale(LC_ALL, "es_CL.UTF-8") != nullptr;
    std::setlocale(LC_ALL, saved.c_str());
    return ok;
}

#define SKIP_WITHOUT_SPANISH_LOCALE()                                                                             \
    if (!haveSpanishLocale())                                                                                     \
    PADROB_NEEDS_COMPONENT("the locale es_CL.UTF-8 is not installed here (scripts/install-deps.sh generates it)")

/// A pendulum written with decimals everywhere; its lower limit is hit within 0.5 s (an
/// event line with a time), and a drive-less joint.
std::string decimalModel()
{
    return writeTemp("decimals.pad",
                     "GRAVITY 0 0 -9.81\n"
                     "B 1 1.5 0.025 0.025 0.0125 CG 0 0 -0.25 NAME \"bob\"\n"
                     "C 1 QI 0.1 VI 0.05 LL 0.05 UL 0.75 NAME \"pivot\"\n"
                     "B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 -1\n"
                     "B2 1 P2 0 0 1.25 A2 1 0 0 R2 0 0 -1\n");
}

}  // namespace

TEST(CliLocale, NumbersAreTheSameUnderASpanishLocale)
{
    SKIP_WITHOUT_SPANISH_LOCALE();
    const std::string model = decimalModel();
    // check: the same output, in English with --lang en
    const CliRun checkC = padrob("check '" + model + "'");
    const CliRun checkEs = padrobWith(kSpanish, "check '" + model + "' --lang en");
    EXPECT_EQ(checkC.status, 0) << checkC.out;
    EXPECT_EQ(checkEs.status, 0) << checkEs.out;
    EXPECT_EQ(checkEs.out, checkC.out);
    // info --json: the same object whatever the language
    const CliRun jsonC = padrob("info --json '" + model + "'");
    const CliRun jsonEs = padrobWith(kSpanish, "info --json '" + model + "'");
    ASSERT_EQ(jsonC.status, 0) << jsonC.err;
    ASSERT_EQ(jsonEs.status, 0) << jsonEs.err;
    EXPECT_EQ(jsonEs.out, jsonC.out);
    EXPECT_NE(jsonC.out.find("\"mass\": 1.5"), std::string::npos) << jsonC.out;
    EXPECT_NE(jsonC.out.find("\"lower_limit\": 0.05"), std::string::npos) << jsonC.out;
    // info as text: the numbers keep the point in Spanish too
    const CliRun textC = padrob("info '" + model + "'");
    const CliRun textEs = padrobWith(kSpanish, "info '" + model + "' --lang en");
    EXPECT_EQ(textEs.out, textC.out);
    const CliRun textSpanish = padrobWith(kSpanish, "info '" + model + "'");
    EXPECT_EQ(textSpanish.status, 0);
    EXPECT_NE(textSpanish.out.find("1.5"), std::string::npos) << textSpanish.out;
    EXPECT_EQ(textSpanish.out.find("1,5"), std::string::npos) << textSpanish.out;
    // simulate: the same CSV byte for byte, and the same event lines (their times with '.')
    const std::string csvC = writeTemp("decimals_c.csv", ""), csvEs = writeTemp("decimals_es.csv", "");
    const CliRun simC = padrob("simulate '" + model + "' --time 0.5 --dt 0.01 --out '" + csvC + "'");
    const CliRun simEs = padrobWith(kSpanish, "simulate '" + model + "' --time 0.5 --dt 0.01 --out '" + csvEs + "' --lang en");
    ASSERT_EQ(simC.status, 0) << simC.err;
    ASSERT_EQ(simEs.status, 0) << simEs.err;
    const std::string c = slurp(csvC), es = slurp(csvEs);
    EXPECT_EQ(es, c);
    EXPECT_NE(c.find("\n0,0.1,0.05,"), std::string::npos) << c.substr(0, 200);  // t, q1, qd1 of the first row
    EXPECT_EQ(simEs.err, simC.err);
    EXPECT_NE(simC.err.find("t=0."), std::string::npos) << simC.err;  // the limit's event
    // options take '.' under es_CL too
    const CliRun dt = padrobWith(kSpanish, "simulate '" + model + "' --time 0.05 --dt 0.025");
    EXPECT_EQ(dt.status, 0) << dt.err;
    EXPECT_EQ(lines(dt.out).size(), 4u) << dt.out;  // the header and t = 0, 0.025, 0.05
}

TEST(CliLocale, LanguageFromTheLocaleOrLang)
{
    SKIP_WITHOUT_SPANISH_LOCALE();
    // the system's language: Spanish under es_CL
    const CliRun es = padrobWith(kSpanish, "--help");
    EXPECT_EQ(es.status, 0);
    EXPECT_EQ(es.out.rfind("Uso: padrob COMANDO", 0), 0u) << es.out;
    EXPECT_NE(es.out.find("check MODELO..."), std::string::npos) << es.out;
    // --lang en under es_CL: English, anywhere on the line
    const CliRun en = padrobWith(kSpanish, "--lang en --help");
    EXPECT_EQ(en.out.rfind("Usage: padrob COMMAND", 0), 0u) << en.out;
    const CliRun enAfter = padrobWith(kSpanish, "check --help --lang=en");
    EXPECT_EQ(enAfter.out.rfind("Usage: padrob check", 0), 0u) << enAfter.out;
    // --lang es under C: Spanish
    const CliRun forced = padrob("check --lang es");
    EXPECT_EQ(forced.status, 2);
    EXPECT_NE(forced.err.find("padrob check: no se indicó ningún modelo"), std::string::npos) << forced.err;
    EXPECT_NE(forced.err.find("Pruebe 'padrob check --help'."), std::string::npos) << forced.err;
    // summaries and plurals
    const std::string model = decimalModel();
    const CliRun check = padrobWith(kSpanish, "check '" + model + "'");
    EXPECT_NE(check.out.find(model + ": correcto\n"), std::string::npos) << check.out;
}

TEST(CliLocale, BadLangIsAUsageError)
{
    for (const char* args : {"--lang xx --help", "check models/pendulum.pad --lang fr", "--lang", "--lang= --help"}) {
        SCOPED_TRACE(args);
        const CliRun r = padrob(args);
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.out, "");
        EXPECT_NE(r.err.find("--lang"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("Try 'padrob --help'."), std::string::npos) << r.err;
    }
}
