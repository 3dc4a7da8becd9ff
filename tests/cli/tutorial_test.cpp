// `padrob tutorial` through the real binary: every shipped tutorial checks clean and
// its demonstration passes (exit 0); a careless run fails (exit 1) with its penalties;
// bad input exits 2 with where and why.

#include "cli_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using test::padrob;

namespace {

std::vector<std::string> shippedTutorials()
{
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(std::string(PADROB_SOURCE_DIR) + "/resources/tutorials")) {
        if (e.path().extension() == ".tut") out.push_back("resources/tutorials/" + e.path().filename().string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(CliTutorial, EveryShippedTutorialChecksCleanAndItsDemonstrationPasses)
{
    const auto all = shippedTutorials();
    ASSERT_GE(all.size(), 4u);
    for (const std::string& t : all) {
        const test::CliRun check = padrob("tutorial " + t);
        EXPECT_EQ(check.status, 0) << t << "\n" << check.err;
        EXPECT_EQ(check.err, "") << t;
        const test::CliRun run = padrob("tutorial " + t + " --demo --json");
        EXPECT_EQ(run.status, 0) << t << "\n" << run.out << run.err;
        EXPECT_NE(run.out.find("\"passed\": true"), std::string::npos) << t << "\n" << run.out;
        EXPECT_NE(run.out.find("\"end_reason\": \"completed\""), std::string::npos) << t;
    }
}

TEST(CliTutorial, EveryShippedTutorialFailsWhenTheOperatorDoesNothing)
{
    // levers left alone for 5 s: the liner stays on its cart, no goal is done
    const std::string path = test::writeTemp("idle.path", "wait=5\n");
    for (const std::string& t : shippedTutorials()) {
        const std::string log = test::writeTemp("idle.log", "");
        padrob("tutorial " + t + " --autopilot '" + path + "' --record '" + log + "'");
        const test::CliRun run = padrob("tutorial " + t + " --input '" + log + "' --json");
        EXPECT_EQ(run.status, 1) << t << "\n" << run.out << run.err;
        EXPECT_NE(run.out.find("\"passed\": false"), std::string::npos) << t << "\n" << run.out;
        EXPECT_NE(run.out.find("\"end_reason\": \"input-ended\""), std::string::npos) << t << "\n" << run.out;
    }
}

TEST(CliTutorial, ACarelessRunFailsWithThePenaltiesItEarned)
{
    // the claws driven straight into the liner on its cart instead of around its edge
    const std::string path = test::writeTemp("careless.path", "1=-90deg\n3=0.9\n");
    const std::string log = test::writeTemp("careless.log", "");
    const test::CliRun rec = padrob("tutorial resources/tutorials/t3_approach.tut --autopilot '" + path + "' --record '" + log + "'");
    EXPECT_EQ(rec.status, 1) << rec.out << rec.err;
    const test::CliRun run = padrob("tutorial resources/tutorials/t3_approach.tut --input '" + log + "'");
    EXPECT_EQ(run.status, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("FAILED"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(" hit "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("(-5.0)"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("to improve:"), std::string::npos) << run.out;
}

TEST(CliTutorial, SwingingTheLinerIntoTheWallIsAHardHitThatEndsTheAttempt)
{
    // T6 flown as T5: the boom not lifted over the blast wall; the liner slews into it at
    // ~0.5 m/s (0.131 rad/s at ~4 m)
    const std::string path = test::writeTemp("wall.path", "1=-90deg\n5=0.413 2=1.46095\n3=0.45\n9=0.1415\n2=1.50\n1=-45deg\n");
    const std::string log = test::writeTemp("wall.log", "");
    padrob("tutorial resources/tutorials/t6_obstacles.tut --autopilot '" + path + "' --record '" + log + "'");
    const test::CliRun run = padrob("tutorial resources/tutorials/t6_obstacles.tut --input '" + log + "' --json");
    EXPECT_EQ(run.status, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("\"end_reason\": \"hard-hit\""), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("\"kind\": \"grasp\""), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("\"detail\": \"the blast wall"), std::string::npos) << run.out;  // the wall (G 101/102)
}

TEST(CliTutorial, InTheMillTheLinerSwungWithTheTelescopeOutHitsTheGrate)
{
    // T7's expert path without pulling the telescope in before the slew
    std::string path = test::slurp(std::string(PADROB_SOURCE_DIR) + "/resources/tutorials/t7_mill.path");
    const auto at = path.find("\n3=0.0\n");
    ASSERT_NE(at, std::string::npos);
    path.erase(at + 1, 6);
    const std::string file = test::writeTemp("t7careless.path", path);
    const std::string log = test::writeTemp("t7careless.log", "");
    padrob("tutorial resources/tutorials/t7_mill.tut --autopilot '" + file + "' --record '" + log + "'");
    const test::CliRun run = padrob("tutorial resources/tutorials/t7_mill.tut --input '" + log + "' --lang es");
    EXPECT_EQ(run.status, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("hard-hit"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("la parrilla de descarga"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("Montaje de la coraza en el molino SAG"), std::string::npos) << run.out;
}

TEST(CliTutorial, CarelessRunsOfEveryStageFailWithTheirPenalties)
{
    struct Case {
        const char* tutorial;
        const char* path;   // the autopilot's careless path
        const char* event;  // an event the run must show
        const char* end;    // its end reason
    };
    const Case cases[] = {
        // the wrist held against its stop, hit at full speed, until the time is up
        {"t1_wrist", "5=0.02\n", "\"kind\": \"limit-bang\"", "time-up"},
        // the telescope slammed out and held there, the head never rolled
        {"t2_extension", "3=1.2\n", "\"kind\": \"limit-bang\"", "time-up"},
        // the claws closed and never opened again
        {"t4_claws", "9=0.14\n", "\"kind\": \"goal\"", "input-ended"},
        // the liner let go in the air (the claws' lever opened until the slower upper claw,
        // C 8, is open: on the fluid-power machine it opens 2.6 times slower than C 9)
        {"t5_grasp", "1=-90deg\n5=0.413 2=1.46095\n3=0.45\n9=0.1415\n2=1.50\n8=-0.02\n", "\"kind\": \"drop\"", "input-ended"},
    };
    for (const Case& c : cases) {
        const std::string tut = std::string("resources/tutorials/") + c.tutorial + ".tut";
        const std::string path = test::writeTemp(std::string(c.tutorial) + ".careless.path", c.path);
        const std::string log = test::writeTemp(std::string(c.tutorial) + ".careless.log", "");
        padrob("tutorial " + tut + " --autopilot '" + path + "' --record '" + log + "'");
        const test::CliRun run = padrob("tutorial " + tut + " --input '" + log + "' --json");
        EXPECT_EQ(run.status, 1) << c.tutorial << "\n" << run.out << run.err;
        EXPECT_NE(run.out.find("\"passed\": false"), std::string::npos) << c.tutorial;
        EXPECT_NE(run.out.find(c.event), std::string::npos) << c.tutorial << "\n" << run.out;
        EXPECT_NE(run.out.find(std::string("\"end_reason\": \"") + c.end + "\""), std::string::npos) << c.tutorial << "\n" << run.out;
    }
}

TEST(CliTutorial, BadInputExitsTwoWithWhereAndWhy)
{
    const std::string bad = test::writeTemp("bad.tut", "TUTORIAL B\nTITLE ES \"a\" EN \"b\"\nMODEL \"nope.pad\"\nGOAL g GRASP\n");
    test::CliRun r = padrob("tutorial '" + bad + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("bad.tut:3:7: error: the model 'nope.pad' cannot be used"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("bad.tut:4:1: error: goal 'g' has no NAME"), std::string::npos) << r.err;

    const std::string corrupt = test::writeTemp("corrupt.log", "# padrob input log 1\n0.0,0,garbage\n");
    r = padrob("tutorial resources/tutorials/t0_reach.tut --input '" + corrupt + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("corrupt.log"), std::string::npos) << r.err;

    r = padrob("tutorial resources/tutorials/t0_reach.tut --demo --input x.log");
    EXPECT_EQ(r.status, 2);
    r = padrob("tutorial");
    EXPECT_EQ(r.status, 2);
    r = padrob("tutorial resources/tutorials/t0_reach.tut --lang fr");
    EXPECT_EQ(r.status, 2);
    r = padrob("tutorial --help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("--demo"), std::string::npos);
}
