// The check that keeps Spanish and English complete (issue 8, docs/glossary.md):
// lupdate is run over today's sources into copies of translations/*.ts, as
// `update_translations` would, and every message must then be finished — none new
// (a tr() text nobody translated), none unfinished, none obsolete or vanished (a text
// the code no longer has) — with the same %1…%9 and %n as its source and its plural
// forms filled. And every shipped tutorial must load, which it does only with both
// languages in every text (the loader's missing-language error).
#include "trainer/training/tutorial.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include <gtest/gtest.h>

#include <filesystem>

namespace {

const QString kSource = QStringLiteral(PADROB_SOURCE_DIR);

struct Message {
    QString context, source, translation, type;
    QStringList forms;  // plural forms
    bool numerus = false;
};

std::vector<Message> readTs(const QString& path, QString* error)
{
    std::vector<Message> out;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = "cannot read " + path;
        return out;
    }
    QXmlStreamReader xml(&f);
    QString context;
    Message m;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto name = xml.name();
            if (name == QLatin1String("context")) context.clear();
            else if (name == QLatin1String("name")) context = xml.readElementText();
            else if (name == QLatin1String("message")) {
                m = Message{};
                m.context = context;
                m.numerus = xml.attributes().value("numerus") == QLatin1String("yes");
            } else if (name == QLatin1String("source")) m.source = xml.readElementText();
            else if (name == QLatin1String("translation")) {
                m.type = xml.attributes().value("type").toString();
                if (!m.numerus) m.translation = xml.readElementText();
            } else if (name == QLatin1String("numerusform")) m.forms << xml.readElementText();
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            out.push_back(m);
        }
    }
    if (xml.hasError()) *error = path + ": " + xml.errorString();
    return out;
}

QSet<QString> placeholders(const QString& s)
{
    static const QRegularExpression re(QStringLiteral("%(L?[1-9]|n|L?n)"));
    QSet<QString> out;
    for (auto it = re.globalMatch(s); it.hasNext();) out.insert(it.next().captured(0).remove('L'));
    return out;
}

/// Runs lupdate over today's translated sources into a copy of translations/padrob_<lang>.ts.
QString updatedCopy(const QString& lang, const QTemporaryDir& dir, QString* log)
{
    const QString copy = dir.filePath("padrob_" + lang + ".ts");
    QFile::copy(kSource + "/translations/padrob_" + lang + ".ts", copy);
    QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
    // the sources lupdate reads: what ide/CMakeLists.txt gives update_translations
    QStringList sources;
    for (const char* folder : {"ide", "trainer", "solver"}) {
        QDirIterator it(kSource + "/" + folder, {"*.cpp", "*.h"}, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) sources << it.next();
    }
    sources.sort();
    QFile list(dir.filePath("sources-" + lang + ".lst"));
    if (!list.open(QIODevice::WriteOnly)) return {};
    list.write(sources.join('\n').toUtf8());
    list.close();
    QProcess lupdate;
    // as update_translations, except that obsolete texts are kept (and so seen)
    lupdate.start(QStringLiteral(PADROB_LUPDATE),
                  {"-locations", "none", "-tr-function-alias", QStringLiteral(PADROB_LUPDATE_ALIASES),
                   "-I", kSource, "@" + list.fileName(), "-ts", copy});
    if (!lupdate.waitForFinished(120000) || lupdate.exitCode() != 0) {
        *log = QString::fromLocal8Bit(lupdate.readAllStandardError() + lupdate.readAllStandardOutput());
        return {};
    }
    *log = QString::fromLocal8Bit(lupdate.readAllStandardOutput());
    return copy;
}

void checkCatalogue(const QString& lang)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QString log, error;
    const QString updated = updatedCopy(lang, dir, &log);
    ASSERT_FALSE(updated.isEmpty()) << "lupdate failed:\n" << log.toStdString();
    const std::vector<Message> messages = readTs(updated, &error);
    ASSERT_TRUE(error.isEmpty()) << error.toStdString();
    ASSERT_GT(messages.size(), 500u) << "lupdate found too few texts:\n" << log.toStdString();
    QStringList problems;
    for (const Message& m : messages) {
        const QString where = "[" + m.context + "] \"" + m.source.left(70) + "\"";
        if (m.type == QLatin1String("obsolete") || m.type == QLatin1String("vanished")) {
            problems << "obsolete (the code no longer has it; run update_translations): " + where;
            continue;
        }
        if (m.type == QLatin1String("unfinished")) {
            problems << "unfinished (new or changed text; translate it in translations/padrob_" + lang + ".ts): " + where;
            continue;
        }
        const QSet<QString> want = placeholders(m.source);
        if (m.numerus) {
            if (m.forms.size() != 2 || m.forms[0].isEmpty() || m.forms[1].isEmpty()) {
                problems << "plural forms missing (two are needed): " + where;
                continue;
            }
            for (const QString& form : m.forms) {
                QSet<QString> got = placeholders(form), need = want;
                // a singular form may spell out "one" instead of %n
                got.remove("%n"), need.remove("%n");
                if (got != need) problems << "placeholders differ from the source in \"" + form + "\": " + where;
            }
        } else if (m.translation.isEmpty()) {
            problems << "empty translation: " + where;
        } else if (placeholders(m.translation) != want) {
            problems << "placeholders differ from the source in \"" + m.translation.left(70) + "\": " + where;
        }
    }
    EXPECT_TRUE(problems.isEmpty()) << problems.size() << " problem(s) in translations/padrob_" << lang.toStdString()
                                    << ".ts:\n  " << problems.join("\n  ").toStdString();
}

}  // namespace

TEST(Catalogue, SpanishIsCompleteAfterLupdate) { checkCatalogue("es"); }

TEST(Catalogue, EnglishIsCompleteAfterLupdate) { checkCatalogue("en"); }

TEST(Catalogue, SpanishUsesTheGlossarysWordForTheLiner)
{
    // the liner (the part) is "coraza"; "lainera" is the machine (docs/glossary.md)
    QString error;
    const std::vector<Message> messages = readTs(kSource + "/translations/padrob_es.ts", &error);
    ASSERT_TRUE(error.isEmpty()) << error.toStdString();
    QStringList wrong;
    static const QRegularExpression liner(QStringLiteral("\\bliners?\\b"), QRegularExpression::CaseInsensitiveOption);
    for (const Message& m : messages) {
        const QString es = m.numerus ? m.forms.join(' ') : m.translation;
        if (m.source.contains(liner) && !m.source.contains("manipulator", Qt::CaseInsensitive) &&
            !es.contains("coraza", Qt::CaseInsensitive) && !es.contains("corazas", Qt::CaseInsensitive))
            wrong << "[" + m.context + "] " + m.source.left(60) + " → " + es.left(60);
    }
    EXPECT_TRUE(wrong.isEmpty()) << "a liner must be a coraza:\n  " << wrong.join("\n  ").toStdString();
}

TEST(Catalogue, EveryShippedTutorialHasBothLanguages)
{
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(PADROB_SOURCE_DIR) + "/resources/tutorials")) {
        if (entry.path().extension() != ".tut") continue;
        ++count;
        solver::Diagnostics diags(entry.path().string());
        const auto tutorial = trainer::loadTutorial(entry.path().string(), diags);
        std::string listing;
        for (const solver::Diagnostic& d : diags) listing += d.format() + "\n";
        EXPECT_TRUE(tutorial) << listing;
        for (const solver::Diagnostic& d : diags) EXPECT_NE(d.code, "missing-language") << d.format();
    }
    EXPECT_GE(count, 8);
}

TEST(Catalogue, ATutorialWithoutSpanishIsRefused)
{
    // the same check, on a tutorial that lacks one language: it does not load
    const std::string model = std::string(PADROB_SOURCE_DIR) + "/models/liner_manipulator.pad";
    const std::string text = "TUTORIAL t LEVEL 0\n"
                             "TITLE EN \"Reach a target\"\n"
                             "MODEL \"" + model + "\"\n"
                             "GOAL target REACH BODY 6 POINT 0 0.48 0 AT -2.10 3.08 1.32 TOL 0.15\n"
                             "  NAME ES \"Lleve las garras a la esfera\" EN \"Bring the claws to the sphere\"\n";
    solver::Diagnostics diags("t.tut");
    EXPECT_FALSE(trainer::loadTutorialText(text, "t.tut", diags));
    std::string listing;
    bool language = false;
    for (const solver::Diagnostic& d : diags) {
        listing += d.format() + "\n";
        if (d.code == "missing-language" && d.message.find("ES") != std::string::npos) language = true;
    }
    EXPECT_TRUE(language) << listing;
}
