#include "host/link/LinkHarness.hpp"

namespace nxtmap::link {

LinkHarness::LinkHarness(SimBrick& brick, Session& pc, const HarnessConfig& config)
    : brick_(brick), pc_(pc), config_(config), toPc_(config.toPc), toBrick_(config.toBrick) {}

void LinkHarness::tick() {
  ++now_;
  brick_.step(now_);
  const double perMs = config_.baud / 10.0 / 1000.0;
  const bool up = now_ >= upAtMs_;

  // Brick -> PC: the brick's UART sends at most the byte rate; the pipe damages bytes.
  creditToPc_ = std::min(creditToPc_ + perMs, 2 * perMs);
  const size_t canSend = static_cast<size_t>(creditToPc_);
  std::vector<uint8_t> out = brick_.transmit(now_, canSend);
  creditToPc_ -= static_cast<double>(out.size());
  if (up) {
    wireToPc_ += out.size();
    const std::vector<uint8_t> arrived = toPc_.pass(out);
    if (!arrived.empty()) pc_.receive(arrived.data(), arrived.size(), now_);
  }

  // PC -> brick: the PC's bytes queue for the same rate.
  if (up) {
    const std::vector<uint8_t> fromPc = pc_.transmit(now_);
    const std::vector<uint8_t> arrived = toBrick_.pass(fromPc);
    brickInbox_.insert(brickInbox_.end(), arrived.begin(), arrived.end());
  }
  creditToBrick_ = std::min(creditToBrick_ + perMs, 2 * perMs);
  std::vector<uint8_t> in;
  while (!brickInbox_.empty() && creditToBrick_ >= 1.0) {
    in.push_back(brickInbox_.front());
    brickInbox_.pop_front();
    creditToBrick_ -= 1.0;
  }
  if (!in.empty()) brick_.receive(in.data(), in.size());
}

bool LinkHarness::runUntil(const std::function<bool()>& done, uint32_t maxMs) {
  const uint32_t end = now_ + maxMs;
  while (now_ < end) {
    if (done()) return true;
    tick();
  }
  return done();
}

void LinkHarness::disconnect(uint32_t downMs) {
  brickInbox_.clear();
  pcInbox_.clear();
  brick_.linkLost();
  pc_.linkLost();
  upAtMs_ = now_ + downMs;
}

}  // namespace nxtmap::link
