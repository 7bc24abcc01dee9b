#include "host/emu/BlueCore.hpp"

#include <algorithm>

namespace nxtmap::emu {

namespace {
constexpr uint64_t kBootCycles = kMckHz / 1000 * 50;  // RESET_INDICATION 50 ms after RESET goes high
constexpr uint64_t kPollCycles = kMckHz / 1000;       // the PC side is polled every millisecond
// The module's own address, 00:16:53:0E:4D:5A (00:16:53 is LEGO's OUI; the rest fixed, so tests can
// expect it), most significant byte first, then the seventh byte LEGO's messages carry (0). Reported for
// GET_LOCAL_ADDR (0x27 -> 0x28) and as the caller's address in REQUEST_CONNECTION.
const std::vector<uint8_t> kBdAddr{0x00, 0x16, 0x53, 0x0E, 0x4D, 0x5A, 0x00};
// The PC that dials in: its name and class of device (major class computer, minor desktop), as LOOKUP_NAME
// reports them. LIST_RESULT's status for a device stored (LEGO's c_comm.iom LR_SUCCESS).
constexpr char kPcName[] = "nxtmap PC";
const std::vector<uint8_t> kPcClass{0x00, 0x01, 0x04, 0x00};
constexpr uint8_t kListSuccess = 0x50;
std::vector<uint8_t> name16(const std::string& s) {
  std::vector<uint8_t> v(16, 0);
  std::copy_n(s.begin(), std::min<size_t>(s.size(), 15), v.begin());
  return v;
}
}  // namespace

void BlueCore::reply(uint8_t cmd, const std::vector<uint8_t>& payload) {
  const auto len = static_cast<uint8_t>(payload.size() + 3);
  unsigned sum = len + cmd;
  for (uint8_t b : payload) sum += b;
  const auto cs = static_cast<uint16_t>(0x10000u - (sum & 0xFFFF));  // RX checksum includes the length
  toArm_.push_back(len);
  toArm_.push_back(cmd);
  toArm_.insert(toArm_.end(), payload.begin(), payload.end());
  toArm_.push_back(static_cast<uint8_t>(cs >> 8));
  toArm_.push_back(static_cast<uint8_t>(cs & 0xFF));
  clock_.poke();
}

void BlueCore::fromArm(uint8_t b) {
  if (!running_) return;
  if (dataMode()) {  // stream data: to the PC while a stream is open, else lost with the link
    if (link_ && connected_ && streamOpen_) {
      burst_.push_back(b);
      burstEndsAt_ = clock_.now + kBurstGapCycles;
      if (burst_.size() >= kMaxBurstBytes) flushBurst();
      clock_.poke();
    }
    return;
  }
  frame_.push_back(b);
  if (frame_.size() < 2 || frame_.size() < static_cast<size_t>(frame_[0]) + 1) return;
  std::vector<uint8_t> f(frame_.begin() + 1, frame_.end());  // cmd, payload, csum
  frame_.clear();
  if (f.size() < 3) {
    ++bad_;
    return;
  }
  unsigned sum = 0;
  for (size_t i = 0; i + 2 < f.size(); ++i) sum += f[i];
  const unsigned cs = (static_cast<unsigned>(f[f.size() - 2]) << 8) | f.back();
  if (((sum + cs) & 0xFFFF) != 0) {
    ++bad_;
    return;
  }  // TX checksum: cmd + payload only
  f.resize(f.size() - 2);
  ++commands_;
  command(f);
}

void BlueCore::command(const std::vector<uint8_t>& f) {
  const uint8_t cmd = f[0];
  switch (cmd) {
    case 0x03:
      portOpen_ = true;
      reply(0x1B, {1, 1});
      break;  // OPEN_PORT -> PORT_OPEN_RESULT
    case 0x1D:
      portOpen_ = false;
      reply(0x1E, {1});
      break;    // CLOSE_PORT
    case 0x09:  // ACCEPT_CONNECTION
      if (f.size() > 1 && f[1] == 1 && requested_) {
        connected_ = true;
        reply(0x13, {1, 1});
      } else {
        requested_ = false;
        reply(0x13, {0, 0});
      }
      break;
    case 0x0B:
      if (connected_) streamOpen_ = true;
      break;  // OPEN_STREAM: CMD line high
    case 0x08:
      flushBurst();  // the stream's last bytes leave before the link closes
      connected_ = requested_ = streamOpen_ = false;
      reply(0x1A, {1, 1});
      break;                          // CLOSE_CONNECTION
    case 0x04: lookUpName(f); break;  // LOOKUP_NAME
    case 0x05:                        // ADD_DEVICE (address, name, class): stored -> LIST_RESULT LR_SUCCESS
      reply(0x17, {kListSuccess});
      break;
    case 0x0C: reply(0x0D, {0, 0}); break;                                     // START_HEART -> HEARTBEAT
    case 0x2F: reply(0x30, {1, 0x1F}); break;                                  // GET_VERSION
    case 0x27: reply(0x28, kBdAddr); break;                                    // GET_LOCAL_ADDR
    case 0x29: reply(0x2C, name16("NXT")); break;                              // GET_FRIENDLY_NAME
    case 0x21: reply(0x22, {1}); break;                                        // SET_FRIENDLY_NAME
    case 0x1C: reply(0x20, {1}); break;                                        // SET_DISCOVERABLE
    case 0x2A: reply(0x2D, {1}); break;                                        // GET_DISCOVERABLE
    case 0x2B: reply(0x2E, {static_cast<uint8_t>(portOpen_ ? 1 : 0)}); break;  // GET_PORT_OPEN
    case 0x33: reply(0x31, {0, 0}); break;                                     // GET_BRICK_STATUSBYTE
    case 0x34: reply(0x32, {1}); break;                                        // SET_BRICK_STATUSBYTE
    case 0x07: reply(0x19, {}); break;                                         // DUMP_LIST -> LIST_DUMP_STOPPED
    case 0x0A: reply(0x1F, {}); break;                                         // PIN_CODE -> PIN_CODE_ACK
    case 0x25: reply(0x26, {}); break;                                         // SET_FACTORY_SETTINGS
    case 0x23: reply(0x24, {0xFF}); break;                                     // GET_LINK_QUALITY
    default: unknown_.push_back(cmd); break;
  }
}

// LOOKUP_NAME [address 7]: the connected PC answers with its name -> LOOKUP_NAME_RESULT [address 7][name 16]
// [class of device 4] (LEGO's firmware asks it after accepting a connection, and adds the PC to its device
// list); any other address is out of reach -> LOOKUP_NAME_FAILURE [address 7].
void BlueCore::lookUpName(const std::vector<uint8_t>& f) {
  std::vector<uint8_t> address(7, 0);
  for (size_t i = 0; i < 7 && 1 + i < f.size(); ++i) address[i] = f[1 + i];
  if (!connected_ || address != kBdAddr) {
    reply(0x12, address);
    return;
  }
  std::vector<uint8_t> p = address;
  const std::vector<uint8_t> name = name16(kPcName);
  p.insert(p.end(), name.begin(), name.end());
  p.insert(p.end(), kPcClass.begin(), kPcClass.end());
  reply(0x11, p);
}

void BlueCore::flushBurst() {
  burstEndsAt_ = kNever;
  if (burst_.empty()) return;
  if (link_ && connected_ && streamOpen_) {
    link_->send(burst_.data(), burst_.size());
    toPc_ += burst_.size();
    ++bursts_;
  }
  burst_.clear();
}

bool BlueCore::hasByteForArm() const {
  if (!running_ || rtsHigh_) return false;
  return dataMode() ? streamOpen_ && !pcIn_.empty() : !toArm_.empty();
}

uint8_t BlueCore::takeByteForArm() {
  const bool stream = dataMode();
  if (stream) ++fromPc_;
  std::deque<uint8_t>& q = stream ? pcIn_ : toArm_;
  const uint8_t b = q.front();
  q.pop_front();
  return b;
}

uint64_t BlueCore::nextEventAt() const {
  uint64_t t = kNever;
  if (bootAt_ != kNever) t = bootAt_;
  if (link_ && running_) t = std::min(t, nextPoll_);
  return std::min(t, burstEndsAt_);
}

void BlueCore::pollLink() {
  if (!link_) return;
  const bool pc = link_->connected();
  if (pc && portOpen_ && !announced_) {  // once per PC connection, as soon as the port is open
    announced_ = true;
    requested_ = true;
    std::vector<uint8_t> p = kBdAddr;
    reply(0x16, p);  // REQUEST_CONNECTION
  }
  if (!pc && pcWasConnected_) {  // the PC hung up: its undelivered bytes go with the link, both ways
    connected_ = requested_ = streamOpen_ = announced_ = false;
    pcIn_.clear();
    burst_.clear();
    burstEndsAt_ = kNever;
    reply(0x1A, {1, 1});  // CLOSE_CONNECTION_RESULT, delivered once the ARM is in command mode
  }
  pcWasConnected_ = pc;
  // Until the brick accepts, and while the input is full, the PC's bytes wait on its side (its
  // transport's window closes: back-pressure, as the radio's flow control would).
  const size_t before = pcIn_.size();
  if (connected_ && before < kPcInputBytes) link_->receive(pcIn_, kPcInputBytes - before);
  if (pcIn_.size() != before) clock_.poke();
}

void BlueCore::advanceTo(uint64_t now) {
  const bool reset = pio_.level(kResetPin) && (pio_.driven() >> kResetPin & 1u);
  if (!reset && running_) {  // held in reset
    running_ = false;
    bootAt_ = kNever;
    toArm_.clear();
    frame_.clear();
    pcIn_.clear();
    burst_.clear();
    burstEndsAt_ = kNever;
    portOpen_ = requested_ = connected_ = streamOpen_ = false;
  }
  if (reset && !running_ && bootAt_ == kNever) bootAt_ = now + kBootCycles;
  if (bootAt_ != kNever && now >= bootAt_) {
    bootAt_ = kNever;
    running_ = true;
    nextPoll_ = now;
    reply(0x14, {});  // RESET_INDICATION
  }
  if (now >= burstEndsAt_) flushBurst();
  if (running_ && link_ && now >= nextPoll_) {
    pollLink();
    nextPoll_ = now + kPollCycles;
  }
}

}  // namespace nxtmap::emu
