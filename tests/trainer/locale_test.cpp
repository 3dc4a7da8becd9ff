// Model files and the trainer's data files keep the '.' whatever the locale. Qt
// applications call setlocale(LC_ALL, "") at start and i18n::install makes es_CL the
// default QLocale in Spanish, so under es_CL.UTF-8 the C library reads and writes "1,5":
// the parsers and writers must not depend on it (docs/glossary.md: model files always use
// the point). Skipped where the locale is not installed (scripts/install-deps.sh makes it).

#include "tests/common/components.h"
#include "solver/pipeline.h"
#include "solver/parse/writer.h"
#include "trainer/input/input_log.h"
#include "trainer/training/camera_path.h"

#include <QLocale>

#include <gtest/gtest.h>

#include <clocale>
#include <string>

namespace {

constexpr const char* kSpanish = "es_CL.UTF-8";
constexpr const char* kNoLocale = "the locale es_CL.UTF-8 is not installed here (scripts/install-deps.sh generates it)";

/// The C library's locale and Qt's default locale set to es_CL for the life of the
/// object; the previous ones are put back after.
class SpanishLocale {
public:
    SpanishLocale()
    {
        const char* old = std::setlocale(LC_ALL, nullptr);
        m_old = old ? old : "C";
        m_ok = std::setlocale(LC_ALL, kSpanish) != nullptr;
        if (m_ok) QLocale::setDefault(QLocale(QLocale::Spanish, QLocale::Chile));
    }
    ~SpanishLocale()
    {
        std::setlocale(LC_ALL, m_old.c_str());
        QLocale::setDefault(m_oldQt);
    }
    SpanishLocale(const SpanishLocale&) = delete;
    SpanishLocale& operator=(const SpanishLocale&) = delete;
    bool ok() const { return m_ok; }

private:
    std::string m_old;
    QLocale m_oldQt;
    bool m_ok = false;
};

const char* const kModel =
    "GRAVITY 0 0 -9.81\n"
    "B 1 1.5 0.25 0.25 0.125 CG 0 0 -0.5 NAME \"bob\"\n"
    "C 1 QI 0.1 LL -1.25 UL 1.25 NAME \"pivot\"\n"
    "B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 -1\n"
    "B2 1 P2 0 0 1 A2 1 0 0 R2 0 0 -1\n";

std::string problems(const solver::CompiledModel& m)
{
    std::string s;
    for (const solver::Diagnostic& d : m.diagnostics) s += d.format() + "\n";
    return s;
}

}  // namespace

TEST(SpanishLocale, ModelFilesKeepThePoint)
{
    SpanishLocale es;
    if (!es.ok()) PADROB_NEEDS_COMPONENT(kNoLocale);
    ASSERT_STREQ(std::localeconv()->decimal_point, ",");  // the C library's numbers are 1,5 now
    const solver::CompiledModel m = solver::compileText(kModel, "es.pad");
    ASSERT_TRUE(m.ok()) << problems(m);
    const solver::BodySpec* bob = m.spec.body(1);
    ASSERT_NE(bob, nullptr);
    EXPECT_EQ(bob->mass, 1.5);
    EXPECT_EQ(bob->inertia.x(), 0.25);
    EXPECT_EQ(bob->inertia.z(), 0.125);
    EXPECT_EQ(bob->cg.z(), -0.5);
    EXPECT_EQ(m.spec.gravity.z(), -9.81);
    ASSERT_EQ(m.spec.joints.size(), 1u);
    EXPECT_EQ(m.spec.joints[0].qi, 0.1);
    EXPECT_EQ(m.spec.joints[0].ll, -1.25);
    EXPECT_EQ(m.spec.joints[0].ul, 1.25);
    // a decimal comma is an error under es_CL too, as everywhere
    const solver::CompiledModel comma = solver::compileText("B 1 1,5 1 1 1\n", "comma.pad");
    EXPECT_FALSE(comma.ok());
    // and the writer writes the point
    const std::string text = solver::parse::writeModel(m.spec);
    EXPECT_NE(text.find(" 1.5 "), std::string::npos) << text;
    EXPECT_EQ(text.find("1,5"), std::string::npos) << text;
    EXPECT_EQ(solver::parse::formatNumber(0.125), "0.125");
    const solver::CompiledModel again = solver::compileText(text, "again.pad");
    ASSERT_TRUE(again.ok()) << problems(again);
    EXPECT_EQ(again.spec.body(1)->mass, 1.5);
}

TEST(SpanishLocale, TrainerFilesKeepThePoint)
{
    SpanishLocale es;
    if (!es.ok()) PADROB_NEEDS_COMPONENT(kNoLocale);
    // a camera path
    trainer::CameraPath path;
    QString error;
    ASSERT_TRUE(trainer::CameraPath::parse("# padrob camera path 1\n0.5  1.25 2 0.5  9.5  -1.5 0.45\n", path, &error))
        << error.toStdString();
    ASSERT_EQ(path.keys().size(), 1u);
    EXPECT_EQ(path.keys()[0].t, 0.5);
    EXPECT_EQ(path.keys()[0].target.x(), 1.25);
    EXPECT_EQ(path.keys()[0].distance, 9.5);
    EXPECT_EQ(path.keys()[0].yaw, -1.5);
    // an input log: times and axis readings
    trainer::InputLog log;
    ASSERT_TRUE(trainer::InputLog::parse("# padrob input log 1\n"
                                         "#device 0 {\"id\":\"sdl:pad\",\"kind\":\"gamepad\",\"name\":\"Pad\","
                                         "\"axes\":[{\"name\":\"X\",\"min\":-1,\"rest\":0,\"max\":1}],\"buttons\":[\"A\"]}\n"
                                         "0.25,0,-0.75,1\n",
                                         log, &error))
        << error.toStdString();
    ASSERT_EQ(log.samples.size(), 1u);
    EXPECT_EQ(log.samples[0].time, 0.25);
    ASSERT_EQ(log.samples[0].axes.size(), 1u);
    EXPECT_EQ(log.samples[0].axes[0], -0.75);
}
