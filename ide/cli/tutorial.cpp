// padrob tutorial: check a tutorial, run it headless against an input log or its own
// demonstration and print the result; record a demonstration with the autopilot.

#include "ide/cli/tutorial.h"

#include "ide/cli/cli_io.h"
#include "ide/cli/json_writer.h"
#include "trainer/training/runner.h"
#include "trainer/training/tutorial.h"

#include <QCoreApplication>
#include <QFile>

#include <cstdio>

namespace ide::cli {

namespace {

std::string tr(const char* s) { return QCoreApplication::translate("padrob tutorial", s).toStdString(); }

std::string help()
{
    return tr("Usage: padrob tutorial FILE [--input LOG | --demo] [OPTIONS]\n"
              "\n"
              "Checks a tutorial file (.tut) and, with --input or --demo, runs it without a window:\n"
              "the input log is replayed through the station profile into the simulation while the\n"
              "tutorial's checker watches the goals, the grasp, collisions, overloads and time, and\n"
              "scores the run. Prints whether it passed, the score breakdown and the events with\n"
              "their times.\n"
              "\n"
              "  --input LOG           replay this input log (raw device readings, as padrob-studio's\n"
              "                        Station and Train workspaces record them)\n"
              "  --demo                replay the tutorial's own demonstration (its DEMO statement)\n"
              "  --profile P           the station profile for the log: a .json file or the name of\n"
              "                        one of the model's profiles (default: the tutorial's PROFILE)\n"
              "  --autopilot PATH --record OUT [--camera CAM]\n"
              "                        fly the joint targets of PATH with the levers of a virtual\n"
              "                        console and record them to OUT (a demonstration; see\n"
              "                        docs/training.md), and a chase camera to CAM, then print\n"
              "                        the result of that run\n"
              "  --lang es|en          language of the tutorial's texts (default: en)\n"
              "  --json                print the result as one JSON object\n"
              "\n"
              "Without --input, --demo or --autopilot it only checks the tutorial and its model.\n"
              "\n"
              "Exit status: 0 the tutorial is fine (checked) or the run passed; 1 the run failed;\n"
              "2 bad input: a usage error, a tutorial with errors, an unreadable log.\n");
}

int usage(const std::string& message)
{
    return usageError("tutorial", message, tr("Try 'padrob tutorial --help'."));
}

std::string fixed(double v, int decimals)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

void printText(const trainer::Tutorial& t, const trainer::TutorialResult& r, const std::string& lang)
{
    const trainer::Scoring& sc = t.scoring();
    std::string stars;
    for (int i = 0; i < 3; ++i) stars += i < r.stars ? "*" : "-";
    std::string out = t.spec.id + " - " + t.title(lang) + ": " + (r.passed ? tr("PASSED") : tr("FAILED")) + " [" + stars +
                      "] " + tr("score") + " " + fixed(r.score, 1) + "/100 (" + tr("pass mark") + " " + fixed(sc.pass, 0) +
                      "), " + fixed(r.time, 2) + " s, " + std::to_string(r.goalsDone) + "/" +
                      std::to_string(t.spec.goals.size()) + " " + tr("goals") + ", " + tr("end") + ": " + r.endReason + "\n";
    for (const trainer::ScoreItem& i : r.breakdown) {
        std::string measure;
        if (i.key == "time") measure = fixed(i.value, 1) + " s (" + tr("par") + " " + fixed(sc.parTime, 0) + " s, " + tr("limit") + " " + fixed(sc.timeLimit, 0) + " s)";
        if (i.key == "path") measure = fixed(i.value, 0) + " % " + tr("efficient") + " (" + fixed(r.pathLength, 2) + " m, " + tr("ideal") + " " + fixed(r.idealLength, 2) + " m)";
        if (i.key == "smooth") measure = tr("RMS jerk") + " " + fixed(i.value, 2) + " m/s3 (" + tr("zero points at") + " " + fixed(sc.jerkReference, 1) + ")";
        if (i.key == "safety") measure = fixed(i.value, 1) + " " + tr("penalty points");
        char line[256];
        std::snprintf(line, sizeof line, "  %-12s %5.1f/%-5.1f %s\n", i.label().toStdString().c_str(), i.points, i.max, measure.c_str());
        out += line;
    }
    out += tr("events:") + "\n";
    for (const trainer::TutorialEvent& e : r.events) {
        char line[512];
        std::snprintf(line, sizeof line, "  %9.3f s  %-13s %s%s\n", e.t, trainer::TutorialEvent::key(e.kind),
                      e.text(&t, lang).toStdString().c_str(), e.penalty > 0 ? (" (-" + fixed(e.penalty, 1) + ")").c_str() : "");
        out += line;
    }
    const QStringList improve = r.improvements();
    if (!improve.isEmpty()) {
        out += tr("to improve:") + "\n";
        for (const QString& s : improve) out += "  - " + s.toStdString() + "\n";
    }
    printOut(out);
}

void printJson(const trainer::Tutorial& t, const trainer::TutorialResult& r, const std::string& lang)
{
    JsonWriter j;
    j.beginObject();
    j.key("tutorial").str(t.spec.id);
    j.key("title").str(t.title(lang));
    j.key("passed").boolean(r.passed);
    j.key("completed").boolean(r.completed);
    j.key("end_reason").str(r.endReason);
    j.key("score").num(r.score);
    j.key("stars").integer(r.stars);
    j.key("pass_mark").num(t.scoring().pass);
    j.key("time").num(r.time);
    j.key("goals_done").integer(r.goalsDone);
    j.key("goals_total").integer(static_cast<long long>(t.spec.goals.size()));
    j.key("breakdown").beginArray();
    for (const trainer::ScoreItem& i : r.breakdown) {
        j.beginObject();
        j.key("key").str(i.key);
        j.key("label").str(i.label().toStdString());
        j.key("value").num(i.value);
        j.key("points").num(i.points);
        j.key("max").num(i.max);
        j.endObject();
    }
    j.endArray();
    j.key("measures").beginObject();
    j.key("path_length").num(r.pathLength);
    j.key("ideal_length").num(r.idealLength);
    j.key("overshoot").num(r.overshoot);
    j.key("rms_jerk").num(r.rmsJerk);
    j.key("penalties").num(r.penalties);
    j.key("final_point").beginArray().num(r.finalPoint.x()).num(r.finalPoint.y()).num(r.finalPoint.z()).endArray();
    j.key("final_axes").beginArray();
    for (int c = 0; c < 3; ++c) j.beginArray().num(r.finalAxes(0, c)).num(r.finalAxes(1, c)).num(r.finalAxes(2, c)).endArray();
    j.endArray();
    if (t.loadBody >= 0) j.key("final_load").beginArray().num(r.finalLoad.x()).num(r.finalLoad.y()).num(r.finalLoad.z()).endArray();
    j.endObject();
    j.key("events").beginArray();
    for (const trainer::TutorialEvent& e : r.events) {
        j.beginObject();
        j.key("t").num(e.t);
        j.key("kind").str(trainer::TutorialEvent::key(e.kind));
        j.key("text").str(e.text(&t, lang).toStdString());
        j.key("detail").str(e.detail);
        j.key("value").num(e.value);
        j.key("penalty").num(e.penalty);
        j.endObject();
    }
    j.endArray();
    j.key("improve").beginArray();
    for (const QString& s : r.improvements()) j.str(s.toStdString());
    j.endArray();
    j.endObject();
    printOut(j.text() + "\n");
}

}  // namespace

int runTutorial(const std::vector<std::string>& args)
{
    std::string file, input, profile, autopilot, record, camera, lang = "en";
    bool demo = false, json = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&](std::string& out) {
            if (i + 1 >= args.size()) return false;
            out = args[++i];
            return true;
        };
        if (a == "-h" || a == "--help") {
            printOut(help());
            return kExitOk;
        } else if (a == "--input" || a == "--profile" || a == "--autopilot" || a == "--record" || a == "--lang" || a == "--camera") {
            std::string v;
            if (!value(v)) return usage(a + tr(" needs a value"));
            (a == "--input" ? input : a == "--profile" ? profile : a == "--autopilot" ? autopilot : a == "--record" ? record
                         : a == "--camera"                                                        ? camera
                                                                                                  : lang) = v;
        } else if (a == "--demo") {
            demo = true;
        } else if (a == "--json") {
            json = true;
        } else if (!a.empty() && a[0] == '-') {
            return usage(tr("unknown option '") + a + "'");
        } else if (file.empty()) {
            file = a;
        } else {
            return usage(tr("one tutorial file at a time"));
        }
    }
    if (file.empty()) return usage(tr("no tutorial file given"));
    if (lang != "es" && lang != "en") return usage(tr("--lang is es or en"));
    if (int(!input.empty()) + int(demo) + int(!autopilot.empty()) > 1) return usage(tr("--input, --demo and --autopilot exclude each other"));
    if (autopilot.empty() != record.empty()) return usage(tr("--autopilot and --record go together"));
    if (!camera.empty() && autopilot.empty()) return usage(tr("--camera goes with --autopilot"));

    solver::Diagnostics diags(file);
    std::shared_ptr<const trainer::Tutorial> tut = trainer::loadTutorial(file, diags);
    for (const solver::Diagnostic& d : diags) printErr(d.format() + "\n");
    if (!tut) return kExitUsage;

    if (input.empty() && !demo && autopilot.empty()) {
        printOut(tut->spec.id + " - " + tut->title(lang) + ": " + tr("OK") + " (" + std::to_string(tut->spec.goals.size()) + " " +
                 tr("goals") + (tut->demoFile.empty() ? ", " + tr("no demonstration") : "") + ")\n");
        return kExitOk;
    }
    trainer::StationProfile stationProfile;
    QString error;
    if (!trainer::tutorialProfile(*tut, QString::fromStdString(profile), stationProfile, &error)) {
        printErr("padrob tutorial: " + error.toStdString() + "\n");
        return kExitUsage;
    }
    trainer::RunOutput run;
    if (!autopilot.empty()) {
        QFile f(QString::fromStdString(autopilot));
        if (!f.open(QIODevice::ReadOnly)) {
            printErr("padrob tutorial: " + autopilot + ": " + f.errorString().toStdString() + "\n");
            return kExitUsage;
        }
        std::vector<trainer::AutopilotWaypoint> path;
        trainer::CameraPath cameraPath;
        if (!trainer::parseAutopilotPath(QString::fromUtf8(f.readAll()), path, &error) ||
            !trainer::recordWithAutopilot(tut, path, stationProfile, QString::fromStdString(record), run, &error,
                                          camera.empty() ? nullptr : &cameraPath)) {
            printErr("padrob tutorial: " + autopilot + ": " + error.toStdString() + "\n");
            return kExitUsage;
        }
        if (!camera.empty() && !cameraPath.save(QString::fromStdString(camera), &error)) {
            printErr("padrob tutorial: " + camera + ": " + error.toStdString() + "\n");
            return kExitUsage;
        }
    } else {
        const std::string logPath = demo ? tut->demoFile : input;
        if (demo && logPath.empty()) {
            printErr("padrob tutorial: " + tr("the tutorial has no usable demonstration (DEMO)") + "\n");
            return kExitUsage;
        }
        auto log = std::make_shared<trainer::InputLog>();
        if (!trainer::InputLog::load(QString::fromStdString(logPath), *log, &error)) {
            printErr("padrob tutorial: " + logPath + ": " + error.toStdString() + "\n");
            return kExitUsage;
        }
        if (!trainer::runTutorialWithLog(tut, log, stationProfile, run, &error)) {
            printErr("padrob tutorial: " + error.toStdString() + "\n");
            return kExitUsage;
        }
    }
    if (json) printJson(*tut, run.result, lang);
    else printText(*tut, run.result, lang);
    return run.result.passed ? kExitOk : kExitModelErrors;
}

}  // namespace ide::cli
