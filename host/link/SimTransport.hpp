// SimTransport: the in-process stand-in brick (SimBrick) behind the Transport interface, on the
// wall clock (optionally sped up), so the console can talk to `sim:WORLD` exactly as to a real
// link. It passes bytes at the radio's 460800 baud.
#pragma once
#include <atomic>
#include <chrono>
#include <memory>

#include "host/link/SimBrick.hpp"
#include "host/link/Transport.hpp"
#include "host/sim/Site.hpp"

#include <optional>

namespace nxtmap::link {

// How the stand-in's robot is simulated: the same choices as `nxtmap sim` (--noise, --robot, --start-jitter,
// --grid).
struct SimTransportOptions {
  sim::NoiseProfile noise;  // default: ideal
  uint64_t seed = 1;
  std::optional<sim::RobotDescription> robot;  // empty: a point robot of the raster's cells (published)
  double startJitterDeg = 0.0;
  mapping::GridCapacity grid = mapping::GridCapacity::brick();  // the stand-in's room grid
};

class SimTransport : public Transport {
 public:
  // Loads the world of a sim: link (any world `nxtmap sim` takes); throws LinkError for a bad world or start.
  explicit SimTransport(const LinkSpec& spec, double speed = 1.0, const SimTransportOptions& options = {});

  size_t read(uint8_t* buffer, size_t capacity, int timeoutMs) override;
  void write(const uint8_t* data, size_t size) override;
  std::string describe() const override { return description_; }
  // The stand-in itself: read it only while no one is reading or writing the transport.
  const SimBrick& brick() const { return *brick_; }
  // Presses the stand-in's Left button (a new room) at its next step; safe from any thread.
  void pressNewRoom() { newRoomPresses_.fetch_add(1); }

 private:
  uint32_t nowMs() const;

  std::unique_ptr<sim::Site> site_;
  std::unique_ptr<SimBrick> brick_;
  std::string description_;
  double speed_;
  std::chrono::steady_clock::time_point start_;
  std::atomic<int> newRoomPresses_{0};
  double credit_ = 0;
  uint32_t lastMs_ = 0;
};

}  // namespace nxtmap::link
