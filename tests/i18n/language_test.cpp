// The built-in catalogues at run time: install() switches the language (and the
// locale's decimal separator) back and forth without a restart, the system locale
// chooses the first language, and the model layer's diagnostics come out translated.
#include "tests/common/components.h"
#include "ide/i18n/diagnostic_text.h"
#include "ide/i18n/language.h"
#include "solver/pipeline.h"

#include <QCoreApplication>
#include <QLocale>

#include <gtest/gtest.h>

#include <clocale>

namespace {

struct English {
    ~English() { i18n::install("en"); }
};

}  // namespace

TEST(Language, InstallSwitchesTextsAndNumbersBothWays)
{
    English restore;
    ASSERT_TRUE(i18n::install("es"));
    EXPECT_EQ(i18n::current(), "es");
    EXPECT_EQ(QCoreApplication::translate("Diagnostics", "warning"), QString("advertencia"));
    EXPECT_EQ(QLocale().toString(1.5, 'f', 1), QString("1,5"));
    EXPECT_EQ(i18n::severityName(solver::Severity::Error), QString("error"));
    ASSERT_TRUE(i18n::install("en"));
    EXPECT_EQ(QCoreApplication::translate("Diagnostics", "warning"), QString("warning"));
    EXPECT_EQ(QLocale().toString(1.5, 'f', 1), QString("1.5"));
    EXPECT_FALSE(i18n::install("fr"));
    EXPECT_EQ(i18n::current(), "en");
}

TEST(Language, NativeNamesAndLocales)
{
    EXPECT_EQ(i18n::languages(), QStringList({"es", "en"}));
    EXPECT_EQ(i18n::nativeName("es"), QString("Español"));
    EXPECT_EQ(i18n::nativeName("en"), QString("English"));
    EXPECT_EQ(i18n::localeFor("es").decimalPoint(), QString(","));
    EXPECT_EQ(i18n::localeFor("es").territory(), QLocale::Chile);
    EXPECT_EQ(i18n::localeFor("en").decimalPoint(), QString("."));
    EXPECT_EQ(i18n::startLanguage("es"), "es");
    EXPECT_EQ(i18n::startLanguage("en"), "en");
}

TEST(Language, ModelDiagnosticsAreTranslatedWithTheirArguments)
{
    English restore;
    // a misspelt keyword: message and hint with the word and the guess in them
    const solver::CompiledModel m = solver::compileText("GRAVITY 0 0 -9.81\nBB 1 1 1 1 1\n", "m.pad");
    const solver::Diagnostic* unknown = nullptr;
    for (const solver::Diagnostic& d : m.diagnostics) {
        if (d.code == "unknown-keyword") unknown = &d;
    }
    ASSERT_TRUE(unknown) << "no unknown-keyword diagnostic";
    const solver::Diagnostic* d = unknown;
    ASSERT_TRUE(i18n::install("es"));
    const QString es = i18n::message(*d);
    EXPECT_TRUE(es.contains("BB")) << es.toStdString();
    EXPECT_FALSE(i18n::hint(*d).isEmpty());
    EXPECT_NE(es.toStdString(), d->message) << "not translated: " << d->message;
    EXPECT_NE(i18n::hint(*d).toStdString(), d->hint) << "hint not translated: " << d->hint;
    EXPECT_TRUE(QString::fromStdString(i18n::format(*d)).startsWith("m.pad:2:1: error: "));
    i18n::install("en");
    EXPECT_EQ(i18n::message(*d).toStdString(), d->message);
    EXPECT_EQ(i18n::format(*d), d->format());
}

TEST(Language, ModelFilesReadPointDecimalsUnderASpanishCLocale)
{
    // Qt applications call setlocale(LC_ALL, ""): a Chilean operator's es_CL.UTF-8 must
    // not make the parser read 1.5 as 1 (docs/glossary.md: model files use the point)
    const char* previous = std::setlocale(LC_ALL, nullptr);
    const std::string saved = previous ? previous : "C";
    if (!std::setlocale(LC_ALL, "es_CL.UTF-8")) PADROB_NEEDS_COMPONENT("the es_CL.UTF-8 locale is not installed (scripts/install-deps.sh makes it)");
    const solver::CompiledModel m = solver::compileText("GRAVITY 0 0 -9.81\nB 1 1.5 0.25 0.25 0.125\nC 1 QI 0.5\n"
                                                         "B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 -1\nB2 1 P2 0 0 1 A2 1 0 0 R2 0 0 -1\n", "m.pad");
    std::setlocale(LC_ALL, saved.c_str());
    ASSERT_FALSE(m.diagnostics.hasErrors()) << (m.diagnostics.empty() ? "" : m.diagnostics.items().front().format());
    ASSERT_FALSE(m.spec.bodies.empty());
    EXPECT_DOUBLE_EQ(m.spec.bodies.front().mass, 1.5);
    EXPECT_DOUBLE_EQ(m.spec.bodies.front().inertia[2], 0.125);
    ASSERT_FALSE(m.spec.joints.empty());
    ASSERT_TRUE(m.spec.joints.front().qi.has_value());
    EXPECT_DOUBLE_EQ(*m.spec.joints.front().qi, 0.5);
}
