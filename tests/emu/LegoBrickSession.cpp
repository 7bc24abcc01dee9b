#include "LegoBrickSession.hpp"

#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/sim/World.hpp"

#include <cstdlib>
#include <deque>
#include <filesystem>

namespace nxtmap::emu::lego {
namespace {

constexpr double kCyclesPerMs = static_cast<double>(kMckHz) / 1000.0;

// The PC's side of the link, counting the radio packets and the telegrams a packet boundary cuts.
class PacketLink : public MemoryLink {
 public:
  size_t packets = 0, cut = 0;
  void send(const uint8_t* d, size_t n) override {
    ++packets;
    for (size_t i = 0; i < n; ++i) {
      if (header_ < 2) {
        length_ |= static_cast<size_t>(d[i]) << (8 * header_);
        if (++header_ == 2) left_ = length_;
      } else {
        --left_;
      }
      if (header_ == 2 && left_ == 0) header_ = length_ = 0;  // a telegram ends
    }
    if (header_ != 0) ++cut;  // the packet ends inside a telegram
    MemoryLink::send(d, n);
  }

 private:
  size_t header_ = 0, length_ = 0, left_ = 0;  // length bytes seen, the telegram's length, its bytes to come
};

// The PC's side of one session: sends the script's groups, pairs replies with requests in order.
class Driver {
 public:
  Driver(const std::vector<Step>& script, const SessionOptions& o, PacketLink& radio, SessionResult& out)
      : script_(script), o_(o), radio_(radio), out_(out) {}

  // One event boundary; true when the script is over.
  bool step(double nowMs, bool streaming, double drivenCm, double motorADeg) {
    motorADeg_ = motorADeg;
    takeReplies(nowMs, drivenCm, motorADeg);
    while (!waiting_.empty() && nowMs - out_.exchanges[waiting_.front()].sentMs > o_.replyTimeoutMs) {
      waiting_.pop_front();  // missing: the next reply goes to the next request
      readyAtMs_ = nowMs + o_.gapMs;
    }
    if (!streaming || nowMs < o_.startAtS * 1000.0 || !waiting_.empty() || nowMs < readyAtMs_) return false;
    if (next_ >= script_.size()) return true;
    sendGroup(nowMs, drivenCm);
    return false;
  }

 private:
  void sendGroup(double nowMs, double drivenCm) {
    do {
      const Bytes& r = script_[next_].request;
      Exchange e;
      e.request = r;
      e.sentMs = nowMs;
      e.drivenCmAtSend = drivenCm;
      e.motorADegAtSend = motorADeg_;
      const Bytes f = framed(r);
      radio_.toBrick.insert(radio_.toBrick.end(), f.begin(), f.end());
      if (replySize(r) > 0) waiting_.push_back(out_.exchanges.size());
      out_.exchanges.push_back(e);
      ++next_;
    } while (next_ < script_.size() && script_[next_].withPrevious);
    readyAtMs_ = nowMs + o_.gapMs;
  }

  void takeReplies(double nowMs, double drivenCm, double motorADeg) {
    if (!radio_.fromBrick.empty()) {
      splitter_.push(radio_.fromBrick.data(), radio_.fromBrick.size());
      radio_.fromBrick.clear();
    }
    Bytes t;
    while (splitter_.pop(t)) {
      if (t.empty() || t[0] != kReply) {
        out_.otherTelegrams.push_back(t);
        continue;
      }
      if (waiting_.empty()) {
        ++out_.extraReplies;
        continue;
      }
      Exchange& e = out_.exchanges[waiting_.front()];
      waiting_.pop_front();
      e.reply.bytes = t;
      e.answered = true;
      e.repliedMs = nowMs;
      e.drivenCmAtReply = drivenCm;
      e.motorADegAtReply = motorADeg;
      if (waiting_.empty()) readyAtMs_ = nowMs + o_.gapMs;
    }
  }

  const std::vector<Step>& script_;
  const SessionOptions& o_;
  PacketLink& radio_;
  SessionResult& out_;
  TelegramSplitter splitter_;
  std::deque<size_t> waiting_;  // exchanges waiting for their reply, oldest first
  size_t next_ = 0;
  double motorADeg_ = 0;
  double readyAtMs_ = 0;
};

}  // namespace

std::string simFirmwarePath() {
  if (const char* env = std::getenv("NXTMAP_FIRMWARE")) return env;  // another image (as make bench takes it)
#ifdef NXTMAP_EMU_FIRMWARE_DIR
  const std::string p = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf";
  return std::filesystem::exists(p) ? p : "";
#else
  return "";
#endif
}

SessionResult runSession(const std::vector<Step>& script, const SessionOptions& o) {
  SessionResult out;
  const std::string elf = o.firmware.empty() ? simFirmwarePath() : o.firmware;
  ElfLoad load = ElfImage::load(elf);
  if (!load.image) {
    out.error = "firmware: " + load.error;
    return out;
  }
  const sim::WorldLoad world =
      sim::World::load(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/occupancy-120.map");
  if (!world.world) {
    out.error = "world: " + world.error;
    return out;
  }
  PacketLink radio;
  EmulatedRunOptions run;
  run.brick.startCol = 1;
  run.brick.startRow = 20;
  run.brick.heading = sim::Heading::N;
  run.brick.link = &radio;
  run.pressEnterAtS = o.drive ? 1.0 : -1.0;
  run.stopWhenExplored = false;
  run.maxSeconds = o.maxSeconds;
  Driver driver(script, o, radio, out);
  EmulatedRun* emulated = nullptr;
  bool over = false;
  run.onEvent = [&](uint64_t cycles) {
    const Brick& b = emulated->brick();
    over = driver.step(static_cast<double>(cycles) / kCyclesPerMs, b.blueCore().streaming(), b.drive().drivenCm(),
                       b.drive().wheelDeg(0));
    return over;
  };
  EmulatedRun e(*load.image, *world.world, run);
  emulated = &e;
  const EmulatedRunReport r = e.run();
  out.endS = r.emulatedSeconds;
  out.packets = radio.packets;
  out.cutTelegrams = radio.cut;
  if (r.fault)
    out.error = "fault: " + r.fault.describe();
  else if (!over)
    out.error = "the script did not finish within " + std::to_string(o.maxSeconds) + " emulated s";
  return out;
}

}  // namespace nxtmap::emu::lego
