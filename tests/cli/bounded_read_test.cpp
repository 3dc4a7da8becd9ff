// Every file padrob reads has a size limit and must be a regular file: a device, a FIFO
// (which would block the run forever) or a huge file is refused with its name and why,
// never read until the memory runs out.

#include "cli_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <sys/stat.h>

using test::padrob;

namespace {

namespace fs = std::filesystem;

fs::path tempDir()
{
    const fs::path dir = fs::temp_directory_path() / ("padrob_cli_bounded_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

/// A FIFO nobody writes to: opening it for reading would block.
std::string fifo()
{
    const std::string path = (tempDir() / "pipe.log").string();
    fs::remove(path);
    EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
    return path;
}

/// A sparse file of `bytes` (no disk used).
std::string huge(const std::string& name, std::uintmax_t bytes)
{
    const fs::path path = tempDir() / name;
    { std::ofstream(path) << "# padrob input log 1\n"; }
    fs::resize_file(path, bytes);
    return path.string();
}

void expectRefused(const test::CliRun& r, const std::string& file, const std::string& why)
{
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("bad_alloc"), std::string::npos) << r.err;
}

}  // namespace

TEST(CliBoundedReads, InputLogsThatAreDevicesFifosOrHugeAreRefused)
{
    // (timeout: before the fix a FIFO blocked the run forever)
    const std::string model = "models/liner_manipulator.pad --time 0.01";
    expectRefused(padrob("simulate " + model + " --input-log /dev/zero"), "/dev/zero", "not a regular file");
    const std::string pipe = fifo();
    expectRefused(padrob("simulate " + model + " --input-log '" + pipe + "'"), pipe, "not a regular file");
    const std::string big = huge("big.log", 300ull << 20);
    expectRefused(padrob("simulate " + model + " --input-log '" + big + "'"), "big.log",
                  "too large for an input log (300.0 MB; the limit is 256 MB)");

    expectRefused(padrob("tutorial resources/tutorials/t0_reach.tut --input /dev/zero"), "/dev/zero", "not a regular file");
    expectRefused(padrob("tutorial resources/tutorials/t0_reach.tut --input '" + pipe + "'"), pipe, "not a regular file");
    expectRefused(padrob("tutorial resources/tutorials/t0_reach.tut --input '" + big + "'"), "big.log", "too large");
}

TEST(CliBoundedReads, AutopilotPathsProfilesDemonstrationsAndCameraPathsAreBounded)
{
    const std::string out = (tempDir() / "rec.log").string();
    expectRefused(padrob("tutorial resources/tutorials/t0_reach.tut --autopilot /dev/zero --record '" + out + "'"), "/dev/zero",
                  "not a regular file");
    const std::string bigPath = huge("big.path", 2u << 20);
    expectRefused(padrob("tutorial resources/tutorials/t0_reach.tut --autopilot '" + bigPath + "' --record '" + out + "'"),
                  "big.path", "too large for an autopilot path (2.0 MB; the limit is 1 MB)");
    EXPECT_FALSE(fs::exists(out));

    const std::string bigProfile = huge("big.json", 2u << 20);
    expectRefused(padrob("tutorial resources/tutorials/t0_reach.tut --input resources/tutorials/t0_reach.demo.log --profile '" +
                         bigProfile + "'"),
                  "big.json", "too large for a station profile");

    // a tutorial whose demonstration and camera path are devices: it still loads (they are
    // warnings), and says so
    const fs::path dir = tempDir();
    const std::string tut = test::slurp(PADROB_SOURCE_DIR "/resources/tutorials/t0_reach.tut");
    std::string text;
    for (std::size_t at = 0; at < tut.size();) {
        std::size_t nl = tut.find('\n', at);
        if (nl == std::string::npos) nl = tut.size();
        std::string line = tut.substr(at, nl - at);
        if (line.rfind("DEMO ", 0) == 0) line = "DEMO \"/dev/zero\" CAMERA \"/dev/urandom\"";
        else if (line.rfind("MODEL ", 0) == 0) line = "MODEL \"" PADROB_SOURCE_DIR "/models/liner_manipulator_fluid.pad\"";
        else if (line.rfind("PROFILE ", 0) == 0) line.clear();
        text += line + "\n";
        at = nl + 1;
    }
    const std::string devices = test::writeTemp("devices.tut", text);
    test::CliRun r = padrob("tutorial '" + devices + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("/dev/zero"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("/dev/urandom"), std::string::npos) << r.err;
    r = padrob("tutorial '" + devices + "' --demo");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
}
