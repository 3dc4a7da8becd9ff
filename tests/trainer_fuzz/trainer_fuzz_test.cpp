// Deterministic mutation fuzzing of the trainer's file readers (issue 23, "Bad input"):
// tutorials (.tut), input logs (.log), camera paths (.cam), autopilot paths (.path)
// and station profiles (.json), from the files Padrob ships, a fixed count of mutants
// each (tests/common/fuzz.h). Built in the default build and under the asan preset
// (PADROB_BUILD_TRAINER), where a read past a buffer or undefined behaviour stops it.
//
// For every mutant the reader must return (no crash, no hang: each within a second
// even under ASan), and:
//   - a tutorial's diagnostics lie inside the text (line, column) and format as
//     "file:L:C: error: …"; a tutorial that parses without errors also resolves
//     (model, scene, targets: loadTutorialText) without a crash for one in four;
//   - a log, camera path or autopilot path is accepted, or refused with a message;
//     an accepted camera path gives finite cameras at every time; an accepted log's
//     samples are in time order with finite readings;
//   - a profile is accepted (and then writes and reads back as the same profile), or
//     refused with at least one error naming what is wrong.

#include "tests/common/fuzz.h"
#include "trainer/input/input_log.h"
#include "trainer/station/profile.h"
#include "trainer/training/camera_path.h"
#include "trainer/training/runner.h"
#include "trainer/training/tutorial.h"

#include <gtest/gtest.h>

#include <QByteArray>
#include <QString>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using test::fuzz::escaped;
using test::fuzz::Mutator;

std::string sourceFile(const std::string& relative)
{
    std::ifstream in(std::string(PADROB_SOURCE_DIR) + "/" + relative, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> vocabulary(std::initializer_list<const char*> words)
{
    std::vector<std::string> v = test::fuzz::commonTokens();
    for (const char* w : words) v.emplace_back(w);
    return v;
}

/// Runs `check` on `count` mutants of `seedText`; `check` returns the first broken
/// invariant ("" when none) and says whether the mutant was accepted.
void fuzz(const std::string& what, const std::string& seedText, std::uint32_t seed, int count,
          const std::vector<std::string>& words, int minAccepted,
          const std::function<std::string(const std::string&, bool&)>& check)
{
    ASSERT_FALSE(seedText.empty()) << what << ": no seed";
    for (int run = 0; run < test::fuzz::fuzzScale(); ++run) {
        const std::uint32_t s = seed + 1000u * static_cast<std::uint32_t>(run);
        Mutator mutator(s, words);
        int accepted = 0;
        double worst = 0;
        for (int k = 0; k < count; ++k) {
            const std::string mutant = mutator.mutate(seedText);
            bool ok = false;
            const auto t0 = std::chrono::steady_clock::now();
            const std::string problem = check(mutant, ok);
            worst = std::max(worst, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            accepted += ok ? 1 : 0;
            if (!problem.empty()) {
                ADD_FAILURE() << what << ", seed " << s << ", mutant " << k << ": " << problem << "\n--- mutant:\n"
                              << escaped(mutant) << "\n---";
                return;
            }
        }
        EXPECT_LT(worst, 1.0) << what << ": the slowest of " << count << " mutants";
        // enough mutants must get through, or the checks after acceptance test little
        EXPECT_GE(accepted, minAccepted) << what << ": accepted " << accepted << " of " << count;
        std::printf("[ fuzz     ] %s seed %u: %d mutants, %d accepted, slowest %.4f s\n", what.c_str(), s, count,
                    accepted, worst);
    }
}

std::string tutorialProblem(const std::string& text, const std::string& file, bool& ok, int& accepted)
{
    solver::Diagnostics diags(file);
    trainer::parseTutorial(text, file, diags);
    const std::vector<int> lengths = test::fuzz::lineLengths(text);
    for (const solver::Diagnostic& d : diags) {
        const std::string f = d.format();
        const bool wholeFile = d.pos == solver::SourcePos{1, 1};
        if (!wholeFile) {
            if (d.pos.line < 1 || d.pos.line > static_cast<int>(lengths.size())) return "line out of the text: " + f;
            const int len = lengths[static_cast<std::size_t>(d.pos.line - 1)];
            if (d.pos.column < 1 || d.pos.column > len + 1) return "column out of its line: " + f;
        }
        if (d.code.empty() || d.message.empty()) return "no code or message: " + f;
        if (d.severity == solver::Severity::Error) {
            const std::string prefix =
                file + ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + ": error: ";
            if (f.compare(0, prefix.size(), prefix) != 0 || f.size() == prefix.size()) return "badly formatted: " + f;
        }
    }
    ok = !diags.hasErrors();
    if (ok && accepted++ % 4 == 0) {
        // resolved against its model and scene: never a crash, errors or a tutorial
        solver::Diagnostics full(file);
        const auto tutorial = trainer::loadTutorialText(text, file, full);
        if (!tutorial && !full.hasErrors()) return "no tutorial and no error";
        if (tutorial && full.hasErrors()) return "a tutorial with errors";
    }
    return {};
}

TEST(TrainerFuzz, Tutorials)
{
    // the file sits where the shipped ones are, so that its MODEL, SCENE and DEMO resolve
    const std::string file = std::string(PADROB_SOURCE_DIR) + "/resources/tutorials/fuzz.tut";
    const auto words = vocabulary({"TUTORIAL", "LEVEL", "TITLE", "INTRO", "PART", "HINT", "GOAL", "WEIGHTS", "TIME",
                                   "LIMIT", "PAR", "PASS", "MODEL", "SCENE", "PROFILE", "DEMO", "CAMERA", "LIMITS",
                                   "DRIVES", "CLAW", "OVERLOAD", "AVOID", "GRIP", "FINGERS", "WORKER", "DROP", "ES",
                                   "EN", "3", "1", "-1", "0.05", "\"../../models/pendulum.pad\""});
    for (const auto& [name, seed] : {std::pair{"t0_reach.tut", 11u}, std::pair{"t5_grasp.tut", 12u},
                                     std::pair{"t7_mill.tut", 13u}}) {
        int accepted = 0;
        fuzz(name, sourceFile(std::string("resources/tutorials/") + name), seed, 600, words, 60,
             [&](const std::string& text, bool& ok) { return tutorialProblem(text, file, ok, accepted); });
    }
}

TEST(TrainerFuzz, InputLogs)
{
    const auto words = vocabulary({"# padrob input log 1", "#device", "{", "}", "[", "]", "\"axes\":", "\"buttons\":",
                                   "\"max\":", "\"min\":", "\"rest\":", "\"kind\":", "\"serial\"", "1", "0",
                                   "-1", "1e6", "0.001", "512"});
    fuzz("t0_reach.demo.log", sourceFile("resources/tutorials/t0_reach.demo.log"), 21, 1500, words, 60,
         [](const std::string& text, bool& ok) -> std::string {
             trainer::InputLog log;
             QString error;
             ok = trainer::InputLog::parse(QByteArray::fromStdString(text), log, &error);
             if (!ok) return error.isEmpty() ? "refused without a message" : "";
             double last = -INFINITY;
             for (const trainer::LoggedSample& s : log.samples) {
                 if (!std::isfinite(s.time) || s.time < last) return "samples out of time order or not finite";
                 last = s.time;
                 if (s.device < 0 || s.device >= log.devices.size()) return "a sample of no device";
                 for (double a : s.axes) {
                     if (!std::isfinite(a)) return "a reading that is not finite";
                 }
             }
             return {};
         });
}

TEST(TrainerFuzz, CameraPaths)
{
    const auto words = vocabulary({"# padrob camera path 1", "1", "0", "-1", "1e300", "3.14159"});
    fuzz("t5_grasp.demo.cam", sourceFile("resources/tutorials/t5_grasp.demo.cam"), 31, 1500, words, 100,
         [](const std::string& text, bool& ok) -> std::string {
             trainer::CameraPath path;
             QString error;
             ok = trainer::CameraPath::parse(QByteArray::fromStdString(text), path, &error);
             if (!ok) return error.isEmpty() ? "refused without a message" : "";
             for (double t : {-1.0, 0.0, 0.37, path.duration() / 2, path.duration(), path.duration() + 5}) {
                 const trainer::CameraKey k = path.at(t);
                 if (!k.target.allFinite() || !std::isfinite(k.distance) || !std::isfinite(k.yaw) ||
                     !std::isfinite(k.pitch)) {
                     return "a camera that is not finite at t = " + std::to_string(t);
                 }
             }
             return {};
         });
}

TEST(TrainerFuzz, AutopilotPaths)
{
    const auto words = vocabulary({"wait=", "wait=1", "=", "1=0.5", "2=-0.3", "1=-90deg", "deg", "#", "1", "0"});
    fuzz("t7_mill.path", sourceFile("resources/tutorials/t7_mill.path"), 41, 1500, words, 100,
         [](const std::string& text, bool& ok) -> std::string {
             std::vector<trainer::AutopilotWaypoint> out;
             QString error;
             ok = trainer::parseAutopilotPath(QString::fromUtf8(QByteArray::fromStdString(text)), out, &error);
             if (!ok && error.isEmpty()) return "refused without a message";
             return {};
         });
}

TEST(TrainerFuzz, StationProfiles)
{
    const auto words = vocabulary({"{", "}", "[", "]", ":", "\"format\":", "\"version\":", "\"model\":",
                                   "\"devices\":", "\"mappings\":", "\"banks\":", "\"calibrations\":", "\"axis\":",
                                   "\"drive\":", "\"gain\":", "\"sign\":", "\"select\":", "\"always\":",
                                   "\"baud\":", "\"device\":", "true", "false", "null", "1", "0", "-1", "1e400"});
    for (const auto& [name, seed] : {std::pair{"console.json", 51u}, std::pair{"gamepad.json", 52u}}) {
        fuzz(name, sourceFile(std::string("models/liner_manipulator.station/") + name), seed, 1500, words, 60,
             [](const std::string& text, bool& ok) -> std::string {
                 trainer::StationProfile profile;
                 QList<trainer::ProfileIssue> issues;
                 ok = trainer::StationProfile::fromJson(QByteArray::fromStdString(text), profile, issues);
                 if (!ok) {
                     for (const trainer::ProfileIssue& i : issues) {
                         if (i.error && !i.message.isEmpty()) return {};
                     }
                     return "refused without an error";
                 }
                 trainer::StationProfile back;
                 QList<trainer::ProfileIssue> again;
                 if (!trainer::StationProfile::fromJson(profile.toJson(), back, again)) {
                     return "its written form does not load: " + profile.toJson().toStdString();
                 }
                 if (!(back == profile)) return "its written form reads back different: " + profile.toJson().toStdString();
                 return {};
             });
    }
}

}  // namespace
