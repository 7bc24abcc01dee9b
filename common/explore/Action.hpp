#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// What an explorer asks the robot to do next. Never blocks: the caller carries it out and
// answers with an Event.
struct Action {
  enum class Kind : uint8_t {
    Read,   // take one filtered reading of `sensor`; answer Event::range
    Move,   // move `amount` cells: +1 forward, -1 backward; answer Event::moved or Event::blocked
    Turn,   // turn `amount` eighths of a turn, + = clockwise (2 = 90 deg right); answer Event::turned
    Done,   // mapping is finished
    Think,  // the explorer needs more CPU before it can decide: answer Event::thought() when
            // convenient (each step's CPU cost stays bounded; nothing moves meanwhile)
  };
  Kind kind = Kind::Done;
  Sensor sensor = Sensor::Front;
  int8_t amount = 0;

  static constexpr Action read(Sensor s) { return Action{Kind::Read, s, 0}; }
  static constexpr Action move(int8_t cells) { return Action{Kind::Move, Sensor::Front, cells}; }
  static constexpr Action turn(int8_t eighths) { return Action{Kind::Turn, Sensor::Front, eighths}; }
  static constexpr Action done() { return Action{Kind::Done, Sensor::Front, 0}; }
  static constexpr Action think() { return Action{Kind::Think, Sensor::Front, 0}; }
};

}  // namespace nxtmap
