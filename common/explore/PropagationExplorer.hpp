#pragma once
#include <cstdint>

#include "common/explore/Explorer.hpp"
#include "common/explore/Propagation.hpp"

namespace nxtmap {

// The published method (sections 3.5, 4.7): the start-up heuristic, the four diagonal
// propagations with deviation around obstacles, wall detection and the transition table, the
// return to the start line after a corner, the stop heuristic, then the sweep of the remaining
// unknown areas (large ones are mapped by a new propagation, small ones by a visit).
class PropagationExplorer final : public Explorer {
 public:
  // One finished propagation, for displays and tests.
  struct Record {
    Propagation propagation;
    PropagationOutcome outcome;
    Cell at;  // where it ended
  };
  static constexpr uint8_t kLogCapacity = 64;

  PropagationExplorer(MapLayers& map, TravelPlanner& planner, const ExplorerConfig& config)
      : Explorer(map, planner, config) {}

  const char* name() const override { return "propagation"; }

  // Finished propagations in order (the oldest are dropped beyond kLogCapacity).
  uint16_t recordCount() const { return records_; }
  const Record& record(uint16_t i) const { return log_[i % kLogCapacity]; }
  uint16_t sweeps() const { return sweeps_; }
  bool sweeping() const { return phase_ == Phase::Sweep || phase_ == Phase::SweepTravel; }
  Propagation current() const { return prop_; }

 protected:
  Action decide() override;
  void onBlocked() override;

 private:
  enum class Phase : uint8_t { Startup, AtStart, Mid, Deviate, Return, Sweep, SweepTravel };

  Action startup();
  Action atStart();
  Action mid();
  Action deviate();
  Action ended(PropagationOutcome o);
  Action sweep();
  bool searchVisit(uint8_t purpose, Cell c, uint16_t cost) override;
  Action searchDone(uint8_t purpose) override;
  enum Search : uint8_t { kReturnLine = 0, kSweepTarget = 1 };
  // The search in progress.
  Cell onRow_{}, onColumn_{};  // return line: the two cells on the start lines
  Cell target_{};              // best cell found
  uint16_t targetCost_ = 0xFFFF;
  uint8_t found_ = 0;
  int16_t gain_ = 0;
  Propagation next_{};  // return line: the propagation after the return
  Action begin(Propagation p);
  bool passable(Cell c) const { return map_.at(c) == CellState::Free; }

  Phase phase_ = Phase::Startup;
  Propagation prop_ = Propagation::ForwardRight;
  Cell origin_{};                                // where the current propagation started (its start lines)
  Cell stepFrom_{};                              // the diagonal step's first cell
  Dir first_ = Dir::North, second_ = Dir::East;  // the step's two moves / deviation and blocked side
  int16_t wallCount_ = 0;                        // consecutive blocked cells beside the current deviation
  uint8_t idleTransitions_ = 0;                  // transitions since the last diagonal step
  bool bigArea_ = false;                         // sweep target is a large unknown area: map it with a propagation
  uint16_t sweeps_ = 0;
  Record log_[kLogCapacity] = {};
  uint16_t records_ = 0;
};

}  // namespace nxtmap
