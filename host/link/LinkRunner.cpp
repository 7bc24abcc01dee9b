#include "host/link/LinkRunner.hpp"

namespace nxtmap::link {

LinkRunner::LinkRunner(Opener opener, const SessionConfig& config, uint32_t retryMs, int waitMs)
    : opener_(std::move(opener)),
      retryMs_(retryMs),
      waitMs_(waitMs),
      session_(config),
      start_(std::chrono::steady_clock::now()) {}

LinkRunner::LinkRunner(InstantOpener opener, const SessionConfig& config, uint32_t retryMs)
    : LinkRunner([open = std::move(opener)](const WaitLimit&) { return open(); }, config, retryMs) {}

LinkRunner::~LinkRunner() { stop(); }

void LinkRunner::start() {
  if (running_.exchange(true)) return;
  thread_ = std::thread([this] { loop(); });
}

void LinkRunner::stop() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
}

uint32_t LinkRunner::nowMs() const {
  return static_cast<uint32_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start_).count());
}

std::string LinkRunner::state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_;
}

void LinkRunner::loop() {
  std::unique_ptr<Transport> transport;
  uint8_t buffer[512];
  while (running_) {
    if (!transport) {
      try {
        transport = opener_(WaitLimit{waitMs_, &running_});
        std::lock_guard<std::mutex> lock(mutex_);
        state_ = "connected to " + transport->describe();
      } catch (const LinkError& e) {
        {
          std::lock_guard<std::mutex> lock(mutex_);
          state_ = std::string("waiting for the brick: ") + e.what();
        }
        ++changes_;
        for (uint32_t waited = 0; waited < retryMs_ && running_; waited += 20) {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        continue;
      }
    }
    try {
      if (dropRequested_.exchange(false)) throw TransportClosed("connection dropped on request");
      const size_t n = transport->read(buffer, sizeof(buffer), 10);
      std::vector<uint8_t> out;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (n > 0) session_.receive(buffer, n, nowMs());
        out = session_.transmit(nowMs());
      }
      if (n > 0) ++changes_;
      if (!out.empty()) transport->write(out.data(), out.size());
    } catch (const TransportClosed& e) {
      transport.reset();
      std::lock_guard<std::mutex> lock(mutex_);
      session_.linkLost();
      state_ = std::string("reconnecting: ") + e.what();
      ++changes_;
    }
  }
}

}  // namespace nxtmap::link
