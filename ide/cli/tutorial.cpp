// padrob tutorial: check a tutorial, run it headless against an input log or its own
// demonstration and print the result; record a demonstration with the autopilot.

#include "ide/cli/tutorial.h"

#include "ide/cli/cli_io.h"
#include "ide/cli/json_writer.h"
#include "ide/i18n/diagnostic_text.h"
#include "ide/i18n/language.h"
#include "solver/core/output_file.h"
#include "trainer/io/read_file.h"
#include "trainer/training/runner.h"
#include "trainer/training/tutorial.h"

#include <QFile>

#include <cstdio>

namespace ide::cli {

namespace {

using i18n::trStd;

std::string help()
{
    return trStd("padrob", "Usage: padrob tutorial FILE [--input LOG | --demo] [OPTIONS]\n"
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
              "  --lang es|en          language of the tutorial's texts and of the messages\n"
              "                        (default: the system's; an option of every command)\n"
              "  --json                print the result as one JSON object\n"
              "\n"
              "Without --input, --demo or --autopilot it only checks the tutorial and its model.\n"
              "\n"
              "Exit status: 0 the tutorial is fine (checked) or the run passed; 1 the run failed;\n"
              "2 bad input: a usage error, a tutorial with errors, an unreadable log.\n");
}

int usage(const std::string& message)
{
    return usageError("tutorial", message);
}

/// How the attempt ended, for a person (the JSON keeps the key).
std::string endText(const std::string& reason)
{
    if (reason == "completed") return trStd("padrob", "every goal done");
    if (reason == "time-up") return trStd("padrob", "the time ran out");
    if (reason == "hard-hit") return trStd("padrob", "a hard hit");
    if (reason == "worker-hit") return trStd("padrob", "a worker was touched");
    if (reason == "input-ended") return trStd("padrob", "the input ended");
    if (reason == "solver-error") return trStd("padrob", "the simulation failed");
    if (reason == "aborted") return trStd("padrob", "stopped");
    return reason;
}

void printText(const trainer::Tutorial& t, const trainer::TutorialResult& r, const std::string& lang)
{
    const trainer::Scoring& sc = t.scoring();
    std::string stars;
    for (int i = 0; i < 3; ++i) stars += i < r.stars ? "*" : "-";
    std::string out = t.spec.id + " - " + t.title(lang) + ": " + (r.passed ? trStd("padrob", "PASSED") : trStd("padrob", "FAILED")) +
                      " [" + stars + "] " +
                      fill(trStd("padrob", "score %1/100 (pass mark %2), %3 s, %4/%5 goals, end: %6"),
                           {fixed(r.score, 1), fixed(sc.pass, 0), fixed(r.time, 2), std::to_string(r.goalsDone),
                            std::to_string(t.spec.goals.size()), endText(r.endReason) + " (" + r.endReason + ")"}) +
                      "\n";
    for (const trainer::ScoreItem& i : r.breakdown) {
        std::string measure;
        if (i.key == "time") {
            measure = fill(trStd("padrob", "%1 s (par %2 s, limit %3 s)"), {fixed(i.value, 1), fixed(sc.parTime, 0), fixed(sc.timeLimit, 0)});
        }
        if (i.key == "path") {
            measure = fill(trStd("padrob", "%1 % efficient (%2 m, ideal %3 m)"), {fixed(i.value, 0), fixed(r.pathLength, 2), fixed(r.idealLength, 2)});
        }
        if (i.key == "smooth") {
            measure = fill(trStd("padrob", "RMS jerk %1 m/s3 (zero points at %2)"), {fixed(i.value, 2), fixed(sc.jerkReference, 1)});
        }
        if (i.key == "safety") measure = fill(trStd("padrob", "%1 penalty points"), {fixed(i.value, 1)});
        out += "  " + pad(i.label().toStdString(), 12) + " " + pad(fixed(i.points, 1), 5, true) + "/" + pad(fixed(i.max, 1), 5) + " " +
               measure + "\n";
    }
    out += trStd("padrob", "events:") + "\n";
    for (const trainer::TutorialEvent& e : r.events) {
        out += "  " + pad(fixed(e.t, 3), 9, true) + " s  " + pad(trainer::TutorialEvent::key(e.kind), 13) + " " +
               e.text(&t, lang).toStdString() + (e.penalty > 0 ? " (-" + fixed(e.penalty, 1) + ")" : std::string()) + "\n";
    }
    const QStringList improve = r.improvements();
    if (!improve.isEmpty()) {
        out += trStd("padrob", "to improve:") + "\n";
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
    std::string file, input, profile, autopilot, record, camera;
    // the language of the tutorial's texts: the CLI's (the global option --lang, main.cpp)
    const std::string lang = i18n::current().toStdString();
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
        } else if (a == "--input" || a == "--profile" || a == "--autopilot" || a == "--record" || a == "--camera") {
            std::string v;
            if (!value(v)) return usage(fill(trStd("padrob", "%1 needs a value"), {a}));
            (a == "--input" ? input : a == "--profile" ? profile : a == "--autopilot" ? autopilot : a == "--record" ? record
                                                                                                  : camera) = v;
        } else if (a == "--demo") {
            demo = true;
        } else if (a == "--json") {
            json = true;
        } else if (!a.empty() && a[0] == '-') {
            return usage(fill(trStd("padrob", "unknown option '%1'"), {a}));
        } else if (file.empty()) {
            file = a;
        } else {
            return usage(trStd("padrob", "one tutorial file at a time"));
        }
    }
    if (file.empty()) return usage(trStd("padrob", "no tutorial file given"));
    if (int(!input.empty()) + int(demo) + int(!autopilot.empty()) > 1) {
        return usage(trStd("padrob", "--input, --demo and --autopilot exclude each other"));
    }
    if (autopilot.empty() != record.empty()) return usage(trStd("padrob", "--autopilot and --record go together"));
    if (!camera.empty() && autopilot.empty()) return usage(trStd("padrob", "--camera goes with --autopilot"));

    solver::Diagnostics diags(file);
    std::shared_ptr<const trainer::Tutorial> tut = trainer::loadTutorial(file, diags);
    for (const solver::Diagnostic& d : diags) printDiagnostic(stderr, d);
    if (!tut) return kExitUsage;

    if (input.empty() && !demo && autopilot.empty()) {
        const int goals = static_cast<int>(tut->spec.goals.size());
        printOut(tut->spec.id + " - " + tut->title(lang) + ": " +
                 (tut->demoFile.empty() ? trStd("padrob", "OK (%n goal(s), no demonstration)", nullptr, goals)
                                        : trStd("padrob", "OK (%n goal(s))", nullptr, goals)) +
                 "\n");
        return kExitOk;
    }
    // what the run writes must not be what it reads (the tutorial, its model, scene,
    // demonstration, camera path, profile, autopilot path, input)
    // (nor the camera path the log)
    std::vector<std::string> reads{file, tut->modelFile, tut->sceneFile, tut->demoFile, tut->cameraFile, profile, autopilot, input};
    for (const std::string& out : {record, camera}) {
        if (out.empty()) continue;
        const std::optional<solver::Text> refusal = solver::outputRefusal(out, reads);
        reads.push_back(out);
        if (refusal) {
            printErr("padrob tutorial: " + i18n::text(*refusal).toStdString() + "\n");
            return kExitUsage;
        }
    }
    trainer::StationProfile stationProfile;
    QString error;
    if (!trainer::tutorialProfile(*tut, QString::fromStdString(profile), stationProfile, &error)) {
        printErr("padrob tutorial: " + error.toStdString() + "\n");
        return kExitUsage;
    }
    trainer::RunOutput run;
    if (!autopilot.empty()) {
        const std::optional<QByteArray> text = trainer::readLimitedFile(
            QString::fromStdString(autopilot), trainer::kMaxAutopilotPathBytes, solver::trText("Tutorials", "an autopilot path"), ".path",
            solver::trText("Tutorials", "an autopilot path is a short text file of waypoints; check that this is one"), &error);
        if (!text) {
            printErr("padrob tutorial: " + autopilot + ": " + error.toStdString() + "\n");
            return kExitUsage;
        }
        std::vector<trainer::AutopilotWaypoint> path;
        trainer::CameraPath cameraPath;
        if (!trainer::parseAutopilotPath(QString::fromUtf8(*text), path, &error) ||
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
            printErr("padrob tutorial: " + trStd("padrob", "the tutorial has no usable demonstration (DEMO)") + "\n");
            return kExitUsage;
        }
        auto log = std::make_shared<trainer::InputLog>();
        if (!trainer::InputLog::load(QString::fromStdString(logPath), *log, &error)) {
            printErr("padrob tutorial: " + error.toStdString() + "\n");
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
