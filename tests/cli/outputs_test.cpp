// Never destroy what is not ours: a run refuses to write over a file it reads (by any
// path or hard link), writes into a device or a FIFO as a stream instead of replacing
// it, and leaves no temporary file behind when it is killed.

#include "cli_run.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <thread>

using test::padrob;

namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("padrob_cli_outputs_" + std::to_string(::getpid())) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string copyModel(const fs::path& dir, const char* name = "liner_manipulator.pad")
{
    const fs::path to = dir / name;
    fs::copy_file(fs::path(PADROB_SOURCE_DIR) / "models" / name, to);
    return to.string();
}

std::vector<std::string> listing(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

void expectRefusedAndUntouched(const test::CliRun& r, const std::string& file, const std::string& before)
{
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("which this run reads"), std::string::npos) << r.err;
    EXPECT_EQ(test::slurp(file), before);
}

}  // namespace

TEST(CliOutputs, ARunNeverWritesOverWhatItReads)
{
    const fs::path dir = freshDir("inputs");
    const std::string model = copyModel(dir);
    const std::string before = test::slurp(model);
    expectRefusedAndUntouched(padrob("simulate '" + model + "' --time 0.01 --out '" + model + "'"), model, before);
    // by another path, and by a hard link
    expectRefusedAndUntouched(padrob("simulate '" + model + "' --time 0.01 --out '" + (dir / "." / "liner_manipulator.pad").string() + "'"),
                              model, before);
    fs::create_hard_link(model, dir / "link.pad");
    expectRefusedAndUntouched(padrob("simulate '" + model + "' --time 0.01 --out '" + (dir / "link.pad").string() + "'"), model, before);
    const std::string input = test::writeTemp("outputs_in.csv", "t,u1,u2,u3,u4,u5,u6,u7,u8,u9\n0,0,1,0,0,0,0,0,0,0\n");
    const std::string inputBefore = test::slurp(input);
    expectRefusedAndUntouched(padrob("simulate '" + model + "' --time 0.01 --input '" + input + "' --out '" + input + "'"), input,
                              inputBefore);
    expectRefusedAndUntouched(padrob("export --mjcf '" + model + "' --out '" + model + "'"), model, before);

    // the tutorial: its own file, its model, its demonstration; the camera path onto the log
    const std::string tut = "resources/tutorials/t0_reach.tut";
    const std::string tutBefore = test::slurp(PADROB_SOURCE_DIR "/" + tut);
    const std::string path = test::writeTemp("outputs.path", "3=0.1\n");
    expectRefusedAndUntouched(padrob("tutorial " + tut + " --autopilot '" + path + "' --record " + tut), PADROB_SOURCE_DIR "/" + tut,
                              tutBefore);
    const std::string demo = PADROB_SOURCE_DIR "/resources/tutorials/t0_reach.demo.log";
    const std::string demoBefore = test::slurp(demo);
    expectRefusedAndUntouched(padrob("tutorial " + tut + " --autopilot '" + path + "' --record '" + demo + "'"), demo, demoBefore);
    const std::string log = (dir / "new.log").string();
    test::CliRun r = padrob("tutorial " + tut + " --autopilot '" + path + "' --record '" + log + "' --camera '" + log + "'");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_FALSE(fs::exists(log));
    // (and the refused runs left nothing behind)
    EXPECT_EQ(listing(dir), (std::vector<std::string>{"liner_manipulator.pad", "link.pad"}));
}

TEST(CliOutputs, DevicesAndFifosAreWrittenIntoNotReplaced)
{
    test::CliRun r = padrob("simulate models/liner_manipulator.pad --time 0.01 --out /dev/null");
    EXPECT_EQ(r.status, 0) << r.err;
    struct stat st {};
    ASSERT_EQ(::stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/null was replaced";
    r = padrob("export --mjcf models/double_pendulum.pad --out /dev/null");
    EXPECT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(::stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));

    // a FIFO: the table comes out of it, and it stays a FIFO
    const fs::path dir = freshDir("fifo");
    const std::string fifo = (dir / "table.csv").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = test::slurp(fifo); });
    r = padrob("simulate models/double_pendulum.pad --time 0.01 --out '" + fifo + "'");
    reader.join();
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(received.rfind("t,q1,", 0), 0u) << received.substr(0, 80);
    ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    EXPECT_EQ(listing(dir), std::vector<std::string>{"table.csv"});
}

TEST(CliOutputs, AKilledRunLeavesNoTemporaryFileAndTheOldOutput)
{
    const fs::path dir = freshDir("killed");
    const std::string out = (dir / "out.csv").string();
    { std::ofstream(out) << "old\n"; }
    const std::string cmd = std::string("cd '") + PADROB_SOURCE_DIR + "' && exec '" + PADROB_CLI +
                            "' simulate models/liner_manipulator.pad --time 100000 --out '" + out + "' 2>/dev/null";
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // well into the run, rows written
    ASSERT_EQ(::kill(pid, SIGKILL), 0);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(listing(dir), std::vector<std::string>{"out.csv"});
    EXPECT_EQ(test::slurp(out), "old\n");
}
