// LinkRunner: runs a Session over a real transport on a background thread, reconnecting when
// the transport drops or cannot be opened yet. Everyone else reaches the session through
// with(), under the runner's lock.
#pragma once
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "host/link/LinkSpec.hpp"
#include "host/link/Session.hpp"
#include "host/link/Transport.hpp"

namespace nxtmap::link {

class LinkRunner {
 public:
  // Makes a fresh transport, waiting at most the limit it is given (may throw LinkError: retried
  // every retryMs). The limit's keepGoing is the runner's: stop() ends an attempt within 20 ms.
  using Opener = std::function<std::unique_ptr<Transport>(const WaitLimit&)>;
  // An opener that never waits (an in-process transport).
  using InstantOpener = std::function<std::unique_ptr<Transport>()>;
  // waitMs: how long one attempt to open the link (and one write on it) may take, 1 .. 3600000.
  LinkRunner(Opener opener, const SessionConfig& config, uint32_t retryMs = 1000, int waitMs = 5000);
  LinkRunner(InstantOpener opener, const SessionConfig& config, uint32_t retryMs = 1000);
  ~LinkRunner();
  LinkRunner(const LinkRunner&) = delete;
  LinkRunner& operator=(const LinkRunner&) = delete;

  void start();
  void stop();

  // Runs f(session) under the lock and returns its result.
  template <class F>
  auto with(F&& f) {
    std::lock_guard<std::mutex> lock(mutex_);
    return f(session_);
  }
  // "connected", "connecting", or why the last attempt failed.
  std::string state() const;
  // Bumped whenever bytes arrive (a cheap "something may have changed" for redraws).
  uint64_t changes() const { return changes_.load(); }
  // Milliseconds since start() (the session's clock).
  uint32_t nowMs() const;
  // Breaks the current connection on purpose (tests); the runner reconnects.
  void dropConnection() { dropRequested_ = true; }

 private:
  void loop();

  Opener opener_;
  uint32_t retryMs_;
  int waitMs_;
  mutable std::mutex mutex_;
  Session session_;
  std::string state_ = "connecting";
  std::atomic<bool> running_{false};
  std::atomic<bool> dropRequested_{false};
  std::atomic<uint64_t> changes_{0};
  std::thread thread_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace nxtmap::link
