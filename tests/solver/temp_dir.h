#pragma once
// A scratch folder for tests that write files: a fresh folder under
// temp_directory_path(), named uniquely so that test runs at the same time do not
// share it, and removed with everything in it when the object goes.

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace solver::test {

class TempDir {
public:
    explicit TempDir(const std::string& name)
    {
        std::random_device rd;
        const auto tick = std::chrono::steady_clock::now().time_since_epoch().count();
        m_dir = std::filesystem::temp_directory_path() /
                ("padrob_" + name + "_" + std::to_string(rd()) + "_" + std::to_string(tick));
        std::filesystem::create_directories(m_dir);
    }
    ~TempDir()
    {
        std::error_code ec;
        std::filesystem::remove_all(m_dir, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& dir() const { return m_dir; }
    std::string path(const std::string& name) const { return (m_dir / name).string(); }

    /// Writes `bytes` to the file `name` (folders created) and returns its path.
    std::string write(const std::string& name, const std::string& bytes) const
    {
        const std::filesystem::path p = m_dir / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << bytes;
        return p.string();
    }

private:
    std::filesystem::path m_dir;
};

}  // namespace solver::test
