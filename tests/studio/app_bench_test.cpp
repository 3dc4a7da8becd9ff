// The real padrob-studio binary as a process (QProcess, on the test's X server with
// the xcb platform): its command line (--help, bad --bench-frames), the frame bench
// `--bench-frames 20 --json --scene sag_mill.pad` (the JSON keys docs/performance.md
// lists, and sane values: positive, percentiles in order — never speed), and a bench
// whose scene cannot be read (it says why and goes on).

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

QString studioBinary()
{
    return QCoreApplication::applicationDirPath() + QStringLiteral("/padrob-studio");
}

QString millScene()
{
    return QStringLiteral(PADROB_SOURCE_DIR "/resources/scenes/sag_mill.pad");
}

struct Run {
    int exitCode = -1;
    QByteArray out, err;
    bool finished = false;
};

/// Runs padrob-studio with `args`, with settings and data in `home` (never the user's);
/// `noDisplay`: with no X or Wayland display to open (xcb would abort without one).
Run runStudio(const QStringList& args, const QString& home, int timeoutMs = 300000, bool noDisplay = false)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    if (noDisplay) {
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    }
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home + QStringLiteral("/config"));
    env.insert(QStringLiteral("XDG_DATA_HOME"), home + QStringLiteral("/data"));
    env.insert(QStringLiteral("PADROB_NO_JOYSTICKS"), QStringLiteral("1"));
    p.setProcessEnvironment(env);
    p.start(studioBinary(), args);
    Run r;
    if (!p.waitForStarted(10000)) return r;
    r.finished = p.waitForFinished(timeoutMs);
    if (!r.finished) {
        p.kill();
        p.waitForFinished(5000);
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

/// A summary {median, p90, p99, max} with positive values in order.
bool saneSummary(const QJsonObject& s, const char* what, bool p90 = true)
{
    const double median = s["median"].toDouble(-1), p99 = s["p99"].toDouble(-1), max = s["max"].toDouble(-1);
    const bool ok = median > 0 && p99 >= median && max >= p99 && (!p90 || s["p90"].toDouble(-1) >= median);
    if (!ok) qWarning("%s: %s", what, QJsonDocument(s).toJson(QJsonDocument::Compact).constData());
    return ok;
}

bool sanePeriods(const QJsonObject& s, const char* what)
{
    const double median = s["median_us"].toDouble(-1), p99 = s["p99_us"].toDouble(-1),
                 p999 = s["p999_us"].toDouble(-1), max = s["max_us"].toDouble(-1);
    const bool ok = s["steps"].toDouble() > 0 && median > 0 && p99 >= median && p999 >= p99 && max >= p999 &&
                    s["min_us"].toDouble(-1) <= median && s["nominal_us"].toDouble() == 1000 &&
                    s["max_jitter_us"].toDouble(-1) >= 0;
    if (!ok) qWarning("%s: %s", what, QJsonDocument(s).toJson(QJsonDocument::Compact).constData());
    return ok;
}

}  // namespace

class AppBenchTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY2(QFile::exists(studioBinary()), qPrintable(studioBinary()));
        QVERIFY(QFile::exists(millScene()));
    }

    void helpListsTheOptions()
    {
        QTemporaryDir home;
        const Run r = runStudio({QStringLiteral("--help")}, home.path(), 60000);
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 0);
        for (const char* option : {"--scene", "--bench-frames", "--views", "--json", "--lighting", "[MODEL]"})
            QVERIFY2(r.out.contains(option), option);
    }

    // --help and --version print their text without a display (issue 25, item 4), and
    // --help in Spanish is Spanish throughout (Qt's own "Options:" and its help options
    // are not all in Debian's qtbase_es)
    void helpAndVersionNeedNoDisplayAndSpeakSpanish()
    {
        QTemporaryDir home;
        const Run version = runStudio({QStringLiteral("--version")}, home.path(), 60000, true);
        QVERIFY(version.finished);
        QCOMPARE(version.exitCode, 0);
        QCOMPARE(version.out.trimmed(), QByteArray("padrob-studio " PADROB_VERSION));
        const Run english = runStudio({"--lang", "en", "--help"}, home.path(), 60000, true);
        QVERIFY(english.finished);
        QCOMPARE(english.exitCode, 0);
        QVERIFY(english.out.contains("Options:"));
        QVERIFY(english.out.contains("Show this help and quit."));
        const Run spanish = runStudio({"--lang", "es", "--help"}, home.path(), 60000, true);
        QVERIFY(spanish.finished);
        QCOMPARE(spanish.exitCode, 0);
        const QString out = QString::fromUtf8(spanish.out);
        QVERIFY2(out.startsWith(QStringLiteral("Uso: ")), qPrintable(out.left(80)));
        QVERIFY(out.contains(QStringLiteral("Opciones:")));
        QVERIFY(out.contains(QStringLiteral("Mostrar esta ayuda y salir.")));
        QVERIFY(out.contains(QStringLiteral("Mostrar la versión y salir.")));
        QVERIFY(out.contains(QStringLiteral("[MODELO]")));
        for (const char* english : {"Usage:", "Options:", "Arguments:", "Displays", "Show this help", "The model file"})
            QVERIFY2(!out.contains(QLatin1String(english)), english);
    }

    void badBenchArgumentsAreRefused()
    {
        QTemporaryDir home;
        for (const QStringList& args : {QStringList{"--bench-frames", "0"}, QStringList{"--bench-frames", "many"},
                                        QStringList{"--bench-frames", "5", "--views", "2"}}) {
            const Run r = runStudio(args, home.path(), 60000);
            QVERIFY(r.finished);
            QCOMPARE(r.exitCode, 2);
            QVERIFY(r.err.contains("--bench-frames"));
        }
    }

    void lightingIsChosenOnTheCommandLine()
    {
        QTemporaryDir home;
        const Run bad = runStudio({"--lighting", "gouraud", "--bench-frames", "2"}, home.path(), 60000);
        QVERIFY(bad.finished);
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("--lighting must be auto, pixel or vertex"), bad.err.constData());
        // the bench says where the light was computed: as asked, and by itself on llvmpipe
        for (const char* lighting : {"pixel", "vertex", "auto"}) {
            const Run r = runStudio({"--bench-frames", "2", "--views", "1", "--json", "--lighting", lighting},
                                    home.path());
            QVERIFY2(r.finished && r.exitCode == 0, r.err.constData());
            const QJsonObject o = QJsonDocument::fromJson(r.out).object();
            const bool software = o["renderer"].toString().contains("llvmpipe");
            const QString expected = QLatin1String(lighting) == QLatin1String("auto")
                                         ? QString::fromLatin1(software ? "vertex" : "pixel")
                                         : QString::fromLatin1(lighting);
            QCOMPARE(o["lighting"].toString(), expected);
        }
    }

    void benchPrintsOneJsonObject()
    {
        QTemporaryDir home;
        const Run r = runStudio({"--bench-frames", "20", "--json", "--scene", millScene()}, home.path());
        QVERIFY2(r.finished, r.err.constData());
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(r.out, &error);
        QVERIFY2(doc.isObject(), qPrintable(error.errorString() + "\n" + QString::fromUtf8(r.out)));
        const QJsonObject o = doc.object();
        qInfo("%s", QJsonDocument(o).toJson(QJsonDocument::Compact).constData());

        QVERIFY(o["model"].toString().endsWith("liner_manipulator_fluid.pad"));
        QVERIFY(o["scene"].toString().endsWith("sag_mill.pad"));
        QVERIFY(!o.contains("scene_error"));
        QCOMPARE(o["frames"].toInt(), 20);
        QCOMPARE(o["window"]["width"].toInt(), 1920);
        QCOMPARE(o["window"]["height"].toInt(), 1080);
        QVERIFY(o["cpus"].toInt() >= 1);
        QVERIFY(o.contains("renderer"));
        QVERIFY(o["lighting"].toString() == "vertex" || o["lighting"].toString() == "pixel");
        // start-up: from the process's start, and from main() (not longer)
        QVERIFY(o["startup_ms"].toDouble() > 0);
        QVERIFY(o["startup_from_main_ms"].toDouble() > 0);
        QVERIFY(o["startup_ms"].toDouble() >= o["startup_from_main_ms"].toDouble() - 10);  // 10 ms ticks

        const QJsonObject views = o["views"].toObject();
        QCOMPARE(views.keys(), QStringList({"1", "3"}));
        for (const QString& n : views.keys()) {
            const QJsonObject v = views[n].toObject();
            QVERIFY(v["viewport"]["width"].toInt() > 100 && v["viewport"]["height"].toInt() > 100);
            const QJsonObject paced = v["paced"].toObject(), unpaced = v["unpaced"].toObject();
            QVERIFY(paced["frames"].toInt() >= 20);
            QVERIFY(saneSummary(paced["interval_ms"].toObject(), "paced interval"));
            QVERIFY(saneSummary(paced["render_ms"].toObject(), "paced render"));
            QVERIFY(sanePeriods(paced["solver"].toObject(), "paced solver"));
            QCOMPARE(unpaced["frames"].toInt(), 20);
            QVERIFY(saneSummary(unpaced["frame_ms"].toObject(), "unpaced frame"));
            QVERIFY(saneSummary(unpaced["render_ms"].toObject(), "unpaced render"));
            QVERIFY(unpaced["fps"].toDouble() > 0);
            QVERIFY(sanePeriods(unpaced["solver"].toObject(), "unpaced solver"));
        }
        // the three screens each draw: more to draw than one
        QVERIFY(views["3"]["viewport"]["width"].toInt() < views["1"]["viewport"]["width"].toInt());

        const QJsonObject solver = o["solver"].toObject();
        QVERIFY(sanePeriods(solver, "solver"));
        QVERIFY(solver["overruns"].toDouble(-1) >= 0);
        QVERIFY(solver["dropped_s"].toDouble(-1) >= 0);
        QVERIFY(solver["step_compute_us_median"].toDouble() > 0);
        QVERIFY(solver["simulated_s"].toDouble() > 0);
        QVERIFY(!solver.contains("error"));

        const QJsonObject latency = o["latency_us"].toObject();
        QCOMPARE(latency["presses"].toInt(), 60);
        QCOMPARE(latency["timeouts"].toInt(), 0);
        QVERIFY(saneSummary(latency, "latency"));
    }

    void benchWithABadSceneSaysWhyAndGoesOn()
    {
        QTemporaryDir home;
        const QString bad = home.filePath("broken_scene.pad");
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("G 1 B 0 BOX 1 1\n");  // a box needs three sizes
        f.close();
        const Run r = runStudio({"--bench-frames", "3", "--views", "1", "--json", "--scene", bad}, home.path());
        QVERIFY2(r.finished, r.err.constData());
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QVERIFY2(o["scene_error"].toString().contains("broken_scene.pad"), r.out.constData());
        QCOMPARE(o["scene"].toString(), QString());
        QCOMPARE(o["views"].toObject().keys(), QStringList({"1"}));
        QVERIFY(o["views"]["1"]["unpaced"]["frame_ms"]["median"].toDouble() > 0);
        QVERIFY(r.err.contains("broken_scene.pad"));
    }
};

QTEST_MAIN(AppBenchTest)
#include "app_bench_test.moc"
