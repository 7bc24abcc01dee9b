#include "host/emu/EmulatedRun.hpp"

namespace nxtmap::emu {

EmulatedRun::EmulatedRun(const ElfImage& image, const sim::World& world, const EmulatedRunOptions& options)
    : image_(image), options_(options) {
    BrickConfig c = options.brick;
    c.pressEnterAtS = options.pressEnterAtS;
    if (!options.timedFunction.empty() && image.symbol(options.timedFunction)) {
        c.machine.timedFunction = options.timedFunction;
        timed_ = true;
    }
    brick_ = std::make_unique<Brick>(image, world, c);
}

std::optional<uint8_t> EmulatedRun::readSymbolByte(const std::string& name) const {
    const auto at = image_.symbol(name);
    uint8_t v = 0;
    if (!at || !brick_->machine().readByte(*at, v)) return std::nullopt;
    return v;
}

std::optional<uint32_t> EmulatedRun::readSymbolWord(const std::string& name) const {
    const auto at = image_.symbol(name);
    if (!at) return std::nullopt;
    uint32_t v = 0;
    for (uint32_t i = 0; i < 4; ++i) {
        uint8_t b = 0;
        if (!brick_->machine().readByte(*at + i, b)) return std::nullopt;
        v |= static_cast<uint32_t>(b) << (8 * i);
    }
    return v;
}

EmulatedRunReport EmulatedRun::run() {
    EmulatedRunReport r;
    const bool hasDone = image_.symbol("g_explorerDone").has_value();
    brick_->runFor(options_.maxSeconds, [&] {
        if (!hasDone) return false;
        const auto d = readSymbolByte("g_explorerDone");
        return d && *d != 0;
    });
    const Machine& m = brick_->machine();
    const MachineStats s = m.stats();
    r.fault = m.fault();
    r.finished = !r.fault && hasDone && readSymbolByte("g_explorerDone").value_or(0) != 0;
    r.emulatedSeconds = secondsFromCycles(s.cycles);
    r.wallSeconds = s.wallSeconds;
    r.executed = s.executed;
    r.irqs = s.irqs;
    r.idles = s.idles;
    r.ram = m.ramUse();
    r.staticRamBudget = image_.symbol("__static_ram");
    r.maxBusy = s.maxBusy;
    if (timed_) {
        r.sensorUpdates = s.timedCalls;
        r.maxPerUpdate = s.maxTimed;
    } else {
        r.sensorUpdates = readSymbolWord("g_sensorUpdates").value_or(0);
    }
    r.avrGood = brick_->avr().goodFrames();
    r.avrBad = brick_->avr().badFrames();
    for (int p = 0; p < 4; ++p) r.pings += brick_->sensor(p).pings();
    r.drivenCm = brick_->drive().drivenCm();
    r.xCm = brick_->robot().xCm();
    r.yCm = brick_->robot().yCm();
    r.headingDeg = brick_->robot().headingDeg();
    return r;
}

}  // namespace nxtmap::emu
