// Helpers of the emulator tests: the probe programs' paths, a small room, a brick with the test port.
#pragma once

#include "host/emu/Brick.hpp"
#include "host/emu/ElfImage.hpp"
#include "host/emu/LinkServer.hpp"
#include "host/sim/World.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace nxtmap::emu::test {

inline std::string probePath(const std::string& name) {
  return std::string(NXTMAP_EMU_PROBE_DIR) + "/" + name + ".elf";
}

// A raw flash image of little-endian ARM words written to `path` and loaded at the flash base.
inline ElfLoad loadWords(const std::string& path, const std::vector<uint32_t>& words) {
  {
    std::ofstream out(path, std::ios::binary);
    for (uint32_t w : words)
      for (int b = 0; b < 4; ++b) out.put(static_cast<char>(w >> (8 * b)));
  }
  return ElfImage::load(path);
}

inline ElfImage loadProbe(const std::string& name) {
  ElfLoad l = ElfImage::load(probePath(name));
  if (!l.image) throw std::runtime_error(l.error);
  return std::move(*l.image);
}

// A 12 x 10 room: walls all round, one pillar.
inline sim::World smallRoom() {
  return sim::World::fromRows({"############", "#..........#", "#..........#", "#..........#", "#.....#....#",
                               "#..........#", "#..........#", "#..........#", "#..........#", "############"});
}

struct ProbeRun {
  ElfImage image;
  sim::World world;
  std::unique_ptr<Brick> brick;
  bool ok = false;
  ProbeRun(const std::string& name, BrickConfig config, double seconds, LinkEndpoint* link = nullptr)
      : image(loadProbe(name)), world(smallRoom()) {
    config.testPort = true;
    config.link = link;
    if (config.startCol == 0) {
      config.startCol = 3;
      config.startRow = 3;
    }
    brick = std::make_unique<Brick>(image, world, config);
    ok = brick->runFor(seconds);
  }
  TestPort& port() { return *brick->testPort(); }
  std::string fault() const { return brick->machine().fault().describe(); }
};

// A TcpLink listening on a free loopback port from `firstPort` on (null if none was free). Different tests start
// from different ports so that parallel test processes rarely try the same one.
inline std::unique_ptr<TcpLink> listenOnFreePort(int firstPort) {
  for (int p = firstPort + ::getpid() % 2000; p < firstPort + 8000; p += 97) {
    try {
      return std::make_unique<TcpLink>(p);
    } catch (const std::runtime_error&) {}
  }
  return nullptr;
}

}  // namespace nxtmap::emu::test
