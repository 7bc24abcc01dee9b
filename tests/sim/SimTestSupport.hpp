// Helpers shared by the simulator tests: fixture paths and throw-away files.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace nxtmap::sim::test {

inline std::string dataPath(const std::string& name) {
    return std::string(NXTMAP_SOURCE_DIR) + "/tests/sim/data/" + name;
}

// A private temporary directory, removed with everything in it when the object goes away.
class TempDir {
public:
    TempDir() : dir_(std::filesystem::temp_directory_path() / ("nxtmap_sim_" + std::to_string(::getpid()))) {
        std::filesystem::create_directories(dir_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string write(const std::string& name, const std::string& content) const {
        const auto p = dir_ / name;
        std::ofstream(p, std::ios::binary) << content;
        return p.string();
    }

private:
    std::filesystem::path dir_;
};

}  // namespace nxtmap::sim::test
