#include "host/link/SimTransport.hpp"

#include "host/worlds/SiteFiles.hpp"

#include <algorithm>
#include <thread>

namespace nxtmap::link {

SimTransport::SimTransport(const LinkSpec& spec, double speed, const SimTransportOptions& options)
    : description_(spec.text + (options.grid.isBrick() ? "" : " (grid " + options.grid.describe() + ")")),
      speed_(speed),
      start_(std::chrono::steady_clock::now()) {
  worlds::SiteLoad load = worlds::loadSite(spec.address, options.robot ? options.robot->cellCm : 10);
  if (!load.site) throw LinkError(load.error);
  site_ = std::make_unique<sim::Site>(std::move(*load.site));
  SimBrickConfig c;
  c.run.noise = options.noise;
  c.run.seed = options.seed;
  c.run.robot = options.robot;
  c.run.startJitterDeg = options.startJitterDeg;
  c.run.grid = options.grid;
  const sim::World* raster = site_->raster ? &*site_->raster : nullptr;
  if (spec.col >= 0) {
    if (!raster) throw LinkError(spec.address + " is a world file: its start is its own (leave out @COL,ROW)");
    c.run.startCol = spec.col;
    c.run.startRow = spec.row;
  } else if (site_->start) {
    c.run.startPose = site_->start;
  } else {
    // The first free cell, scanning rows from the top.
    bool found = false;
    for (int r = 0; r < raster->height() && !found; ++r) {
      for (int col = 0; col < raster->width() && !found; ++col) {
        if (!raster->blocked(col, r)) {
          c.run.startCol = col;
          c.run.startRow = r;
          found = true;
        }
      }
    }
    if (!found) throw LinkError("world " + spec.address + " has no free cell to start in");
  }
  if (!c.run.startPose &&
      (!raster->inside(c.run.startCol, c.run.startRow) || raster->blocked(c.run.startCol, c.run.startRow))) {
    throw LinkError("start cell " + std::to_string(c.run.startCol) + "," + std::to_string(c.run.startRow) +
                    " is not a free cell of " + spec.address);
  }
  brick_ = std::make_unique<SimBrick>(*site_, c);
}

uint32_t SimTransport::nowMs() const {
  const auto elapsed = std::chrono::steady_clock::now() - start_;
  return static_cast<uint32_t>(std::chrono::duration<double, std::milli>(elapsed).count() * speed_);
}

size_t SimTransport::read(uint8_t* buffer, size_t capacity, int timeoutMs) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
  while (true) {
    const uint32_t now = nowMs();
    for (int n = newRoomPresses_.exchange(0); n > 0; --n) brick_->newRoom();
    brick_->step(now);
    credit_ = std::min(credit_ + (now - lastMs_) * 46.08, 4096.0);
    lastMs_ = now;
    const std::vector<uint8_t> out = brick_->transmit(now, std::min(capacity, static_cast<size_t>(credit_)));
    if (!out.empty()) {
      credit_ -= static_cast<double>(out.size());
      std::copy(out.begin(), out.end(), buffer);
      return out.size();
    }
    if (std::chrono::steady_clock::now() >= deadline) return 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void SimTransport::write(const uint8_t* data, size_t size) { brick_->receive(data, size); }

}  // namespace nxtmap::link
