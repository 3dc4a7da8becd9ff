// padrob-studio [--scene FILE] [--lang es|en] [--lighting auto|pixel|vertex] [MODEL]: the
// application (see app/main_window.h).
// padrob-studio --screenshot FILE [MODEL]: the normal start, the window saved to FILE once
// the model is drawn, then quit (app/frame_bench.h).
// padrob-studio --help | --version: the text only, without a display (no QApplication).
// padrob-studio --trainer [--operator ID] [--lang es|en]: kiosk mode, only the Train
// workspace, full screen (Ctrl+Shift+F12 and the trainer's PIN leave it).
// padrob-studio --bench-frames N [--scene FILE] [--views 1|3] [--json] [MODEL]: how
// fast it starts and draws and how steady its real-time loop is (app/frame_bench.h).
// padrob-studio --display-of STATION [--view left|centre|right] [NETWORK]: a display
// node of the training centre (centre/display_window.h).
// padrob-studio --instructor [--centre-key FILE] [NETWORK]: the instructor's station
// (centre/instructor_window.h). NETWORK: --domain N, --loopback, --interface I, --peer A,
// --security DIR (DDS Security; the node's identity is DIR/nodes/NAME: --name NAME for the
// instructor and the display, the station's own name for --station-name).
// padrob-studio --station-name NAME --centre-key FILE [NETWORK] [MODEL]: the application,
// its Train workspace a station of the training centre (centre/train_station.h).
#include "ide/studio/app/frame_bench.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/train/train_page.h"
#include "ide/studio/view/viewport.h"
#include "ide/i18n/language.h"
#ifdef PADROB_HAVE_DDS
#include "ide/studio/centre/display_window.h"
#include "ide/studio/centre/instructor_window.h"
#include "ide/studio/centre/train_station.h"
#endif

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QSettings>
#include <QSurfaceFormat>

#include <clocale>
#include <cstdio>
#include <memory>
#include <string_view>

namespace {

/// True when the command line asks for a text only (--help, --version): then the
/// application is a QCoreApplication, which needs no display.
bool asksForTextOnly(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        // (--help-all is no option here: its error needs no display either)
        if (a == "-h" || a == "-?" || a == "--help" || a == "--help-all" || a == "-v" || a == "--version") return true;
    }
    return false;
}

}  // namespace

int main(int argc, char** argv)
{
    QElapsedTimer sinceMain;  // the bench's start-up time is measured from here too
    sinceMain.start();
    QSurfaceFormat::setDefaultFormat(studio::Viewport::surfaceFormat());  // OpenGL 3.3 core, before the app
    std::unique_ptr<QCoreApplication> app;
    if (asksForTextOnly(argc, argv)) app = std::make_unique<QCoreApplication>(argc, argv);
    else app = std::make_unique<QApplication>(argc, argv);
    // Qt set the C library's locale from the system's (setlocale(LC_ALL, "")): keep its
    // numbers in C, so that whatever formats or reads a number with the C library (the
    // solver's messages, libraries reading files) uses '.' under es_CL too. What a person
    // reads is formatted by QLocale in the chosen language (docs/i18n.md).
    std::setlocale(LC_NUMERIC, "C");
    QApplication::setOrganizationName("Padrob");
    QApplication::setApplicationName("padrob-studio");
    QApplication::setApplicationVersion(PADROB_VERSION);
    // the language: --lang's (read before the parser, whose --help is translated), else
    // the one chosen last (Settings ▸ Language, the kiosk's start screen), else the
    // system's
    QString requested;
    const QStringList args = QCoreApplication::arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--lang") && i + 1 < args.size()) requested = args[i + 1];
        else if (args[i].startsWith(QLatin1String("--lang="))) requested = args[i].mid(7);
    }
    i18n::install(i18n::startLanguage(requested));

    // the command line (after the translators: --help is translated)
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "studio::main", "Padrob Studio: write a machine's model, simulate it in real time and drive it from the "
                        "operator's devices."));
    // --help and --version of our own: Qt's descriptions of them are not all in its
    // Spanish catalogue (Debian 12's qtbase_es), and --help must read entirely in Spanish
    const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help"), QStringLiteral("?")},
                                  QCoreApplication::translate("studio::main", "Show this help and quit."));
    const QCommandLineOption version(QStringList{QStringLiteral("v"), QStringLiteral("version")},
                                     QCoreApplication::translate("studio::main", "Show the version and quit."));
    parser.addOptions({help, version});
    parser.addPositionalArgument(
        QCoreApplication::translate("studio::main", "model"),
        QCoreApplication::translate("studio::main", "The model file to open (default: the liner manipulator)."),
        QCoreApplication::translate("studio::main", "[MODEL]"));
    const QCommandLineOption scene(
        QStringLiteral("scene"),
        QCoreApplication::translate("studio::main",
                                    "Draw the ground graphics of FILE around the model (a scene such as "
                                    "resources/scenes/sag_mill.pad). Without it, the scene used last."),
        QCoreApplication::translate("studio::main", "FILE"));
    const QCommandLineOption bench(
        QStringLiteral("bench-frames"),
        QCoreApplication::translate("studio::main",
                                    "Measure instead of working, then quit: the start-up time, N frames of a "
                                    "1920x1080 window paced at 60 Hz and N back to back, with one view and with "
                                    "three, the solver's step periods meanwhile, and the latency of 60 key presses "
                                    "to the solver."),
        QStringLiteral("N"));
    const QCommandLineOption views(
        QStringLiteral("views"),
        QCoreApplication::translate("studio::main", "With --bench-frames: only one view (1) or only three (3)."),
        QStringLiteral("1|3"));
    const QCommandLineOption json(
        QStringLiteral("json"),
        QCoreApplication::translate("studio::main", "With --bench-frames: print the results as one JSON object."));
    const QCommandLineOption trainerMode(
        QStringLiteral("trainer"),
        QCoreApplication::translate("studio::main", "Kiosk mode for the training room: only the Train workspace, "
                                                    "full screen, without menus. Ctrl+Shift+F12 leaves it (asking "
                                                    "the trainer's PIN when one is set)."));
    const QCommandLineOption operatorId(
        QStringLiteral("operator"),
        QCoreApplication::translate("studio::main", "With --trainer: the operator in training."),
        QStringLiteral("ID"));
    const QCommandLineOption lang(
        QStringLiteral("lang"),
        QCoreApplication::translate("studio::main", "The language of the application and the tutorials (es or en)."),
        QStringLiteral("es|en"));
    const QCommandLineOption lighting(
        QStringLiteral("lighting"),
        QCoreApplication::translate("studio::main",
                                    "Where the 3D view computes its light: at every pixel (finer), at the vertices "
                                    "(faster on a software OpenGL), or auto: at the vertices on a software OpenGL, "
                                    "at every pixel on a GPU. Without it, the choice made in Settings > Lighting "
                                    "(auto at first; --bench-frames: auto)."),
        QStringLiteral("auto|pixel|vertex"));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QCoreApplication::translate("studio::main", "Start as usual, save the window to FILE (PNG) once the model is "
                                                    "drawn, print the model's file, and quit."),
        QCoreApplication::translate("studio::main", "FILE"));
    parser.addOptions({scene, bench, views, json, trainerMode, operatorId, lang, lighting, screenshot});
#ifdef PADROB_HAVE_DDS
    // the training centre (docs/training-centre.md)
    const QCommandLineOption displayOf(
        QStringLiteral("display-of"),
        QCoreApplication::translate("studio::main", "Be a display node of the training centre: show STATION's "
                                                    "machine from its operator's seat, driven by its state stream."),
        QCoreApplication::translate("studio::main", "STATION"));
    const QCommandLineOption viewSide(
        QStringLiteral("view"),
        QCoreApplication::translate("studio::main", "With --display-of: which of the station's three screens "
                                                    "(default centre)."),
        QStringLiteral("left|centre|right"));
    const QCommandLineOption instructor(
        QStringLiteral("instructor"),
        QCoreApplication::translate("studio::main", "Be the instructor's station of the training centre: watch "
                                                    "the stations and command them."));
    const QCommandLineOption centreKey(
        QStringLiteral("centre-key"),
        QCoreApplication::translate("studio::main", "With --instructor, --display-of or --station-name: the "
                                                    "centre's key, which signs everything a node of the centre "
                                                    "says and checks everything it hears (without it the "
                                                    "instructor and the display see nothing, and the station "
                                                    "refuses every command and is heard by no one)."),
        QCoreApplication::translate("studio::main", "FILE"));
    const QCommandLineOption domain(
        QStringLiteral("domain"),
        QCoreApplication::translate("studio::main", "The training centre's DDS domain, 0-232 (default 0)."),
        QStringLiteral("N"));
    const QCommandLineOption loopback(
        QStringLiteral("loopback"),
        QCoreApplication::translate("studio::main", "The training centre on this computer only."));
    const QCommandLineOption netInterface(
        QStringLiteral("interface"),
        QCoreApplication::translate("studio::main", "The network interface of the training centre (name or "
                                                    "address; repeatable)."),
        QCoreApplication::translate("studio::main", "INTERFACE"));
    const QCommandLineOption peer(
        QStringLiteral("peer"),
        QCoreApplication::translate("studio::main", "Find the centre's other computers by unicast at ADDRESS "
                                                    "(repeatable; without it, multicast)."),
        QCoreApplication::translate("studio::main", "ADDRESS"));
    const QCommandLineOption stationName(
        QStringLiteral("station-name"),
        QCoreApplication::translate("studio::main", "Make the Train workspace a station of the training centre "
                                                    "named NAME (unique in the centre): it publishes its attempt "
                                                    "and obeys the instructor's signed commands."),
        QCoreApplication::translate("studio::main", "NAME"));
    const QCommandLineOption security(
        QStringLiteral("security"),
        QCoreApplication::translate("studio::main", "DDS Security: authenticated, access-controlled, encrypted "
                                                    "traffic, with the centre's PKI in DIR and this node's identity "
                                                    "in DIR/nodes/NAME (see 'padrob centre pki')."),
        QCoreApplication::translate("studio::main", "DIR"));
    const QCommandLineOption nodeName(
        QStringLiteral("name"),
        QCoreApplication::translate("studio::main", "With --instructor or --display-of: this node's name in the "
                                                    "centre (its identity in the PKI with --security). Default: "
                                                    "instructor@HOST, display-STATION-VIEW."),
        QCoreApplication::translate("studio::main", "NAME"));
    parser.addOptions({displayOf, viewSide, instructor, centreKey, domain, loopback, netInterface, peer, stationName,
                       security, nodeName});
#endif
    parser.process(*app);  // a wrong option ends here
    if (parser.isSet(help)) parser.showHelp(0);
    if (parser.isSet(version)) parser.showVersion();
    if (!qobject_cast<QApplication*>(app.get())) {
        // "--help" was an option's value (--scene --help): the windows after all
        app.reset();
        app = std::make_unique<QApplication>(argc, argv);
        std::setlocale(LC_NUMERIC, "C");
        i18n::install(i18n::current());
    }
    if (parser.isSet(lang) && parser.value(lang) != "es" && parser.value(lang) != "en") {
        std::fputs(qPrintable(QCoreApplication::translate("studio::main", "--lang must be es or en.") +
                              QLatin1Char('\n')),
                   stderr);
        return 2;
    }
    const QString model = parser.positionalArguments().value(0);
    // the 3D views' lighting: the option, else the one chosen last (not when measuring)
    {
        studio::Viewport::Lighting l = studio::Viewport::Lighting::Automatic;
        if (parser.isSet(lighting)) {
            if (!studio::Viewport::lightingFromName(parser.value(lighting), l)) {
                std::fputs(qPrintable(QCoreApplication::translate("studio::main",
                                                                  "--lighting must be auto, pixel or vertex.") +
                                      QLatin1Char('\n')),
                           stderr);
                return 2;
            }
        } else if (!parser.isSet(bench)) {
            studio::Viewport::lightingFromName(QSettings().value(QStringLiteral("view/lighting")).toString(), l);
        }
        studio::Viewport::setLighting(l);
    }

    if (parser.isSet(bench)) {
        studio::FrameBenchOptions options;
        bool ok = false;
        options.frames = parser.value(bench).toInt(&ok);
        const QString viewCount = parser.value(views);
        if (!ok || options.frames < 1 || (parser.isSet(views) && viewCount != "1" && viewCount != "3")) {
            std::fputs(qPrintable(QCoreApplication::translate("studio::main",
                                                              "--bench-frames needs a number of frames (1 or more) "
                                                              "and --views 1 or 3.") +
                                  QLatin1Char('\n')),
                       stderr);
            return 2;
        }
        options.views = parser.isSet(views) ? viewCount.toInt() : 0;
        options.json = parser.isSet(json);
        options.modelPath = model;
        options.scenePath = parser.value(scene);
        options.sinceMain = sinceMain;
        return studio::runFrameBench(options);
    }

#ifdef PADROB_HAVE_DDS
    const auto fail = [](const QString& message) {
        std::fputs(qPrintable(message + QLatin1Char('\n')), stderr);
        return 2;
    };
    // the network options (--display-of, --instructor, --station-name)
    trainer::centre::BusOptions net;
    if (parser.isSet(displayOf) || parser.isSet(instructor) || parser.isSet(stationName)) {
        if (parser.isSet(domain)) {
            bool ok = false;
            net.domain = parser.value(domain).toInt(&ok);
            if (!ok || net.domain < 0 || net.domain > 232)
                return fail(QCoreApplication::translate("studio::main", "--domain must be a whole number from 0 to 232."));
        }
        net.interfaces = parser.values(netInterface);
        net.peers = parser.values(peer);
        if (parser.isSet(loopback)) {
            net.interfaces = {QStringLiteral("127.0.0.1")};
            net.peers = {QStringLiteral("127.0.0.1")};
        }
        // DDS Security: this node's identity is DIR/nodes/NAME (the windows choose a
        // default NAME when none is given: instructor@HOST, display-STATION-VIEW)
        net.securityDir = parser.value(security);
        if (parser.isSet(stationName)) net.node = parser.value(stationName).trimmed();
        else if (parser.isSet(nodeName)) net.node = parser.value(nodeName).trimmed();
    }
    if (parser.isSet(stationName) && parser.value(stationName).trimmed().isEmpty())
        return fail(QCoreApplication::translate("studio::main", "--station-name needs a name."));
    if (parser.isSet(displayOf) || parser.isSet(instructor)) {
        if (parser.isSet(instructor)) {
            studio::InstructorWindow window(net, parser.value(centreKey));
            window.show();
            return QApplication::exec();
        }
        studio::DisplayView::Screen side = studio::DisplayView::Centre;
        if (parser.isSet(viewSide) && !studio::DisplayWindow::parseScreen(parser.value(viewSide), &side))
            return fail(QCoreApplication::translate("studio::main", "--view must be left, centre or right."));
        if (parser.isSet(centreKey)) {
            QString error;
            if (!net.key.load(parser.value(centreKey), &error)) return fail(error);
        }
        studio::DisplayWindow window(parser.value(displayOf), side, net);
        window.resize(1280, 720);
        window.show();
        return QApplication::exec();
    }
#endif

    studio::MainWindow window;
    window.openInitial(model);
    if (parser.isSet(scene)) window.loadScene(parser.value(scene));
    else window.restoreScene();
    if (parser.isSet(operatorId)) window.trainPage()->setOperator(parser.value(operatorId));
    if (parser.isSet(trainerMode)) window.setKioskMode(true);  // shows it full screen
    else window.show();
    if (parser.isSet(screenshot)) return studio::saveScreenshot(window, parser.value(screenshot));
    // the first run: how to run, drive and look around (not in kiosk mode: no Help menu there)
    if (!parser.isSet(trainerMode)) window.showGettingStartedOnce();
#ifdef PADROB_HAVE_DDS
    // the Train workspace as a station of the centre (destroyed before the window: it withdraws)
    std::unique_ptr<studio::TrainStation> trainStation;
    if (parser.isSet(stationName)) {
        window.setWorkspace(studio::MainWindow::Workspace::Train);
        studio::TrainStationOptions o;
        o.name = parser.value(stationName).trimmed();
        o.keyFile = parser.value(centreKey);
        o.network = net;
        trainStation = studio::TrainStation::forPage(window.trainPage(), o);
    }
#endif
    return QApplication::exec();
}
