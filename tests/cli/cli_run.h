#pragma once
// Runs the real `padrob` binary for the CLI tests: output, errors, exit status.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace test {

struct CliRun {
    int status = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};

inline std::string slurp(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The locale every test runs padrob in unless it says otherwise: C (English, '.'), with
/// UTF-8 (Qt warns under plain C), and no LANGUAGE, so that a developer's Spanish
/// locale does not change the output the tests compare.
inline const char* const kCLocale = "LC_ALL=C.UTF-8 LANG=C.UTF-8";

/// Runs `PROGRAM ARGS` in the source tree with the environment `env` (env(1)'s arguments:
/// "NAME=VALUE …", "-u NAME"; LANGUAGE removed); captures stdout, stderr and the exit status.
inline CliRun runWith(const std::string& program, const std::string& env, const std::string& args)
{
    static int counter = 0;
    const auto dir = std::filesystem::temp_directory_path() / ("padrob_cli_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string errFile = (dir / ("err" + std::to_string(counter++))).string();
    const std::string cmd = std::string("cd '") + PADROB_SOURCE_DIR + "' && env -u LANGUAGE -u LC_MESSAGES " + env + " '" +
                            program + "' " + args + " 2>'" + errFile + "'";
    CliRun r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
    int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.err = slurp(errFile);
    std::filesystem::remove(errFile);
    return r;
}

/// Runs `padrob ARGS` with the environment variables `env` (runWith).
inline CliRun padrobWith(const std::string& env, const std::string& args) { return runWith(PADROB_CLI, env, args); }

/// Runs `padrob ARGS` in the C locale (kCLocale): English messages.
inline CliRun padrob(const std::string& args) { return padrobWith(kCLocale, args); }

inline std::string writeTemp(const std::string& name, const std::string& text)
{
    const auto dir = std::filesystem::temp_directory_path() / ("padrob_cli_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}


inline std::vector<std::string> lines(const std::string& s)
{
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < s.size()) {
        std::size_t nl = s.find('\n', start);
        if (nl == std::string::npos) nl = s.size();
        out.push_back(s.substr(start, nl - start));
        start = nl + 1;
    }
    return out;
}


}  // namespace test
